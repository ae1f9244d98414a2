// Surface normals and surface tension accelerations computed on the GPU
// against the same functors on the host (label gpu; skipped, with the
// reason, where no GPU is present). Building this file checks that the
// functors are valid device code.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../cuda_test_support.cuh"
#include "backend/cuda_exec.cuh"
#include "backend/device.h"
#include "sph/particle_grid.h"
#include "sph/surface_tension_akinci2013.h"

namespace dp {
namespace {

using test::DeviceSet;

class surface_tension_CudaAgreement : public test::RequiresGpu {};

// The GPU contracts multiply-adds (FMA) and the host does not: the results
// differ by rounding only, measured against the largest magnitude.
void expect_close(const std::vector<Vec3>& host, const std::vector<Vec3>& device, float relative) {
  ASSERT_EQ(host.size(), device.size());
  float scale = 0;
  for (Vec3 v : host) scale = std::fmax(scale, length(v));
  ASSERT_GT(scale, 0.0f);
  for (std::size_t i = 0; i < host.size(); ++i)
    ASSERT_LT(length(host[i] - device[i]), relative * scale) << "particle " << i;
}

TEST_F(surface_tension_CudaAgreement, NormalsAndAccelerationsMatchTheHost) {
  CudaExec exec(0);
  const float s = 0.01f;
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * s);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vec3> liquid_points, rigid_points;
  std::vector<MassUnits> units;
  std::vector<float> density, volume, adhesion;
  for (int i = 0; i < 14; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 10; ++k) {
        liquid_points.push_back(s * Vec3{i + 0.4f * u(rng), j + 0.4f * u(rng), k + 0.4f * u(rng)});
        units.push_back(static_cast<MassUnits>((0.2f + 0.8f * u(rng)) * kFullParticleUnits));
        density.push_back(800.0f + 300.0f * u(rng));
      }
  for (int i = -2; i < 16; ++i)
    for (int j = -2; j < 14; ++j) {
      rigid_points.push_back(Vec3{i * s, j * s, -0.8f * s});
      volume.push_back((0.8f + 0.6f * u(rng)) * s * s * s);
      adhesion.push_back(10.0f * u(rng));
    }
  UniformGrid g;
  g.origin = Vec3{-0.04f, -0.04f, -0.04f};
  g.cell_size = kernel.h;
  g.nx = 11;
  g.ny = 10;
  g.nz = 9;
  DeviceSet liquid, rigid;
  liquid.build(exec, liquid_points, g);
  rigid.build(exec, rigid_points, g);
  units = liquid.to_sorted(units);
  density = liquid.to_sorted(density);
  volume = rigid.to_sorted(volume);
  adhesion = rigid.to_sorted(adhesion);

  CudaExec::Buffer<MassUnits> d_units;
  CudaExec::Buffer<float> d_density, d_volume, d_adhesion;
  CudaExec::upload(d_units, units);
  CudaExec::upload(d_density, density);
  CudaExec::upload(d_volume, volume);
  CudaExec::upload(d_adhesion, adhesion);
  const std::size_t n = liquid_points.size();
  CudaExec::Buffer<Vec3> d_normal(n), d_tension(n);
  const float m = 1000.0f * s * s * s;
  const SurfaceTensionParameters params{kernel, m, 1000.0f, 2.0f};

  exec.parallel_for(n, ComputeSurfaceNormal{liquid.device_view(), CudaExec::ptr(d_units), CudaExec::ptr(d_density),
                                            kernel, m, CudaExec::ptr(d_normal)});
  exec.parallel_for(n, ComputeSurfaceTensionAcceleration{liquid.device_view(), rigid.device_view(), CudaExec::ptr(d_units),
                                                         CudaExec::ptr(d_density), CudaExec::ptr(d_normal),
                                                         CudaExec::ptr(d_volume), CudaExec::ptr(d_adhesion), params,
                                                         CudaExec::ptr(d_tension)});
  exec.synchronize();

  std::vector<Vec3> normal(n), tension(n);
  ComputeSurfaceNormal host_normal{liquid.host_view(), units.data(), density.data(), kernel, m, normal.data()};
  for (std::size_t i = 0; i < n; ++i) host_normal(i);
  ComputeSurfaceTensionAcceleration host_tension{liquid.host_view(), rigid.host_view(), units.data(), density.data(),
                                                 normal.data(), volume.data(), adhesion.data(), params,
                                                 tension.data()};
  for (std::size_t i = 0; i < n; ++i) host_tension(i);

  expect_close(normal, CudaExec::download(d_normal), 1e-5f);
  expect_close(tension, CudaExec::download(d_tension), 1e-4f);
}

}  // namespace
}  // namespace dp
