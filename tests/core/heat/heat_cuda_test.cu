// The heat kernels on the GPU against the same functors run on the host
// (label gpu; skipped, with the reason, where no GPU is present). Compiling
// this file is itself a check: the functors must be valid device code.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../cuda_test_support.cuh"
#include "backend/cuda_exec.cuh"
#include "backend/device.h"
#include "sph/heat_cleary_monaghan1999.h"
#include "sph/mass_units.h"
#include "sph/particle_grid.h"

namespace dp {
namespace {

using test::DeviceSet;

class heat_CudaAgreement : public test::RequiresGpu {};

TEST_F(heat_CudaAgreement, RatesMatchTheHostWithinRounding) {
  CudaExec exec(0);
  const float s = 0.01f;
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * s);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vec3> pl, pr;
  for (int i = 0; i < 3000; ++i) pl.push_back(0.12f * Vec3{u(rng), u(rng), u(rng)});
  for (int i = 0; i < 1500; ++i) pr.push_back(Vec3{0.12f * u(rng), 0.12f * u(rng), -0.06f * u(rng)});
  UniformGrid g;
  g.origin = Vec3{-0.03f, -0.03f, -0.09f};
  g.cell_size = kernel.h;
  g.nx = g.ny = 10;
  g.nz = 12;
  DeviceSet liquid, rigid;
  liquid.build(exec, pl, g);
  rigid.build(exec, pr, g);

  std::vector<float> tl, tr, density, volume;
  std::vector<MassUnits> units;
  for (std::size_t i = 0; i < pl.size(); ++i) {
    tl.push_back(280.0f + 60.0f * u(rng));
    density.push_back(900.0f + 200.0f * u(rng));
    units.push_back(static_cast<MassUnits>((0.3f + 0.7f * u(rng)) * kFullParticleUnits));
  }
  for (std::size_t i = 0; i < pr.size(); ++i) {
    tr.push_back(280.0f + 60.0f * u(rng));
    volume.push_back((0.5f + u(rng)) * s * s * s);
  }
  tl = liquid.to_sorted(tl);
  density = liquid.to_sorted(density);
  units = liquid.to_sorted(units);
  tr = rigid.to_sorted(tr);
  volume = rigid.to_sorted(volume);
  const float m = 1000.0f * s * s * s;
  std::vector<float> mass(pl.size()), liquid_volume(pl.size());
  for (std::size_t i = 0; i < pl.size(); ++i) {
    ParticleMass{units.data(), m, mass.data()}(i);
    ParticleVolume{mass.data(), density.data(), liquid_volume.data()}(i);
  }
  CudaExec::Buffer<float> d_tl, d_tr, d_mass, d_liquid_volume, d_volume, d_rl(pl.size()), d_rr(pr.size());
  CudaExec::upload(d_tl, tl);
  CudaExec::upload(d_tr, tr);
  CudaExec::upload(d_mass, mass);
  CudaExec::upload(d_liquid_volume, liquid_volume);
  CudaExec::upload(d_volume, volume);

  auto liquid_of = [&](GridView v, const float* t, const float* mj, const float* vj) {
    return ThermalParticles::liquid(v, t, mj, vj, 0.6f, 4186.0f);
  };
  auto rigid_of = [&](GridView v, const float* t, const float* vb) {
    return ThermalParticles::rigid(v, t, vb, 7850.0f, 50.0f, 490.0f);
  };
  ThermalParticles dl = liquid_of(liquid.device_view(), CudaExec::ptr(d_tl), CudaExec::ptr(d_mass),
                                  CudaExec::ptr(d_liquid_volume));
  ThermalParticles db = rigid_of(rigid.device_view(), CudaExec::ptr(d_tr), CudaExec::ptr(d_volume));
  exec.parallel_for(pl.size(), ComputeTemperatureRate{dl, db, true, kernel, CudaExec::ptr(d_rl)});
  exec.parallel_for(pr.size(), ComputeTemperatureRate{db, dl, true, kernel, CudaExec::ptr(d_rr)});
  exec.synchronize();

  ThermalParticles hl = liquid_of(liquid.host_view(), tl.data(), mass.data(), liquid_volume.data());
  ThermalParticles hb = rigid_of(rigid.host_view(), tr.data(), volume.data());
  std::vector<float> rl(pl.size()), rr(pr.size());
  ComputeTemperatureRate host_liquid{hl, hb, true, kernel, rl.data()}, host_rigid{hb, hl, true, kernel, rr.data()};
  for (std::size_t i = 0; i < pl.size(); ++i) host_liquid(i);
  for (std::size_t i = 0; i < pr.size(); ++i) host_rigid(i);

  // The GPU contracts multiply-adds (FMA), the host does not: rounding only.
  auto compare = [](const std::vector<float>& host, const std::vector<float>& device) {
    float scale = 0;
    for (float x : host) scale = std::fmax(scale, std::fabs(x));
    for (std::size_t i = 0; i < host.size(); ++i) ASSERT_NEAR(device[i], host[i], 1e-5f * scale) << "particle " << i;
  };
  compare(rl, CudaExec::download(d_rl));
  compare(rr, CudaExec::download(d_rr));
}

}  // namespace
}  // namespace dp
