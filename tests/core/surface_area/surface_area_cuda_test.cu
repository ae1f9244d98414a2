// The surface area kernel on the GPU against the same functor run on the
// host (label gpu; skipped, with the reason, where no GPU is present).
// Compiling this file is itself a check: the functor must be valid device
// code.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../cuda_test_support.cuh"
#include "backend/cuda_exec.cuh"
#include "backend/device.h"
#include "sph/particle_grid.h"
#include "sph/surface_area_orthmann2013.h"

namespace dp {
namespace {

using test::DeviceSet;

class surface_area_CudaAgreement : public test::RequiresGpu {};

TEST_F(surface_area_CudaAgreement, AreasMatchTheHostWithinRounding) {
  CudaExec exec(0);
  const float s = 0.01f;
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * s);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vec3> pl, pw;
  for (int i = 0; i < 3000; ++i) pl.push_back(Vec3{0.12f * u(rng), 0.12f * u(rng), 0.01f + 0.1f * u(rng)});
  for (int i = 0; i < 1500; ++i) pw.push_back(Vec3{0.12f * u(rng), 0.12f * u(rng), 0.01f * u(rng)});
  UniformGrid g;
  g.origin = Vec3{-0.03f, -0.03f, -0.03f};
  g.cell_size = kernel.h;
  g.nx = g.ny = g.nz = 10;
  DeviceSet liquid, wall;
  liquid.build(exec, pl, g);
  wall.build(exec, pw, g);

  // Inputs are per sorted particle; their values need not follow any order.
  std::vector<MassUnits> units;
  std::vector<float> density, wall_volume;
  for (std::size_t i = 0; i < pl.size(); ++i) {
    units.push_back(static_cast<MassUnits>((0.2f + 0.8f * u(rng)) * kFullParticleUnits));
    density.push_back(900.0f + 200.0f * u(rng));
  }
  for (std::size_t i = 0; i < pw.size(); ++i) wall_volume.push_back((1.0f + u(rng)) * s * s * s);
  CudaExec::Buffer<MassUnits> d_units;
  CudaExec::Buffer<float> d_density, d_wall_volume, d_area(pl.size());
  CudaExec::upload(d_units, units);
  CudaExec::upload(d_density, density);
  CudaExec::upload(d_wall_volume, wall_volume);
  const float gamma = flat_face_area_calibration(kernel, s);

  exec.parallel_for(pl.size(), ComputeSurfaceArea{liquid.device_view(), CudaExec::ptr(d_units), CudaExec::ptr(d_density),
                                                  1e-3f, wall.device_view(), CudaExec::ptr(d_wall_volume), true,
                                                  kernel, gamma, CudaExec::ptr(d_area)});
  exec.synchronize();
  std::vector<float> area(pl.size());
  ComputeSurfaceArea host{liquid.host_view(), units.data(), density.data(), 1e-3f, wall.host_view(),
                          wall_volume.data(), true, kernel, gamma, area.data()};
  for (std::size_t i = 0; i < pl.size(); ++i) host(i);

  std::vector<float> device = CudaExec::download(d_area);
  float scale = 0;
  for (float x : area) scale = std::fmax(scale, x);
  // The GPU contracts multiply-adds (FMA), the host does not: rounding only.
  for (std::size_t i = 0; i < area.size(); ++i) ASSERT_NEAR(device[i], area[i], 1e-5f * scale) << "particle " << i;
}

}  // namespace
}  // namespace dp
