// The surface-texture kernels on the GPU against the same functors on the
// host (label gpu; skipped, with the reason, where no GPU is present):
// Eq. 7 (rigid particles -> texel temperatures) and the wetting history.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "../cuda_test_support.cuh"
#include "sph/boundary_akinci2012.h"
#include "surface/texel_temperature_bonet2002.h"
#include "surface/wetting_history_wang2005.h"
#include "surface_scenes.h"

namespace dp {
namespace {

using test::DeviceSet;

class surface_CudaAgreement : public test::RequiresGpu {};

// The host side runs the same functors one index at a time.
template <class F>
void on_host(std::size_t n, const F& f) {
  for (std::size_t i = 0; i < n; ++i) f(i);
}

// Texel -> rigid neighbour list on the host, as NeighborListBuffers builds it.
struct HostList {
  std::vector<std::uint32_t> count, offset, index;
  NeighborList build(const std::vector<Vec3>& query, const GridView& set, float radius) {
    count.assign(query.size() + 1, 0);
    on_host(query.size(), CountNeighbors{query.data(), set, radius * radius, count.data()});
    offset.assign(query.size() + 1, 0);
    for (std::size_t i = 0; i < query.size(); ++i) offset[i + 1] = offset[i] + count[i];
    index.resize(offset.back());
    on_host(query.size(), FillNeighbors{query.data(), set, radius * radius, offset.data(), index.data()});
    return NeighborList{offset.data(), index.data()};
  }
};

TEST_F(surface_CudaAgreement, TexelTemperaturesAndWettingMatchTheHost) {
  CudaExec gpu(0);
  const float s = 0.01f;
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2 * s);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // A bumpy rigid sheet, texels on and near it, liquid above.
  std::vector<Vec3> rigid, texel, normal, liquid;
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) rigid.push_back(Vec3{i * s, 0.002f * u(rng), j * s});
  for (int i = 0; i < 20000; ++i) {
    texel.push_back(Vec3{0.29f * u(rng), 0.004f * u(rng), 0.29f * u(rng)});
    normal.push_back(Vec3{0, 1, 0});
  }
  for (int i = 0; i < 2000; ++i) liquid.push_back(Vec3{0.29f * u(rng), 0.002f + 0.05f * u(rng), 0.29f * u(rng)});
  UniformGrid g;
  g.origin = Vec3{-0.05f, -0.05f, -0.05f};
  g.cell_size = kernel.h;
  g.nx = g.ny = g.nz = 20;
  DeviceSet rigid_set, liquid_set;
  rigid_set.build(gpu, rigid, g);
  liquid_set.build(gpu, liquid, g);

  std::vector<float> temperature;
  for (std::size_t k = 0; k < rigid.size(); ++k) temperature.push_back(280.0f + 60.0f * u(rng));
  temperature = rigid_set.to_sorted(temperature);
  std::vector<float> volume(rigid.size());
  on_host(rigid.size(), ComputeBoundaryVolume{rigid_set.host_view(), kernel, volume.data()});
  // The first 600 of the 900 particles (setup order) are the texels' rigid.
  const std::uint32_t first = 0, count = 600;

  HostList host_lists;
  const NeighborList host_list = host_lists.build(texel, rigid_set.host_view(), kernel.h);
  std::vector<float> host_weight(host_lists.index.size()), host_T(texel.size(), 1.0f);
  on_host(texel.size(), ComputeTexelWeights{host_list, texel.data(), rigid_set.host_position.data(), volume.data(),
                                                     rigid_set.host_order.data(), first, count, kernel, host_weight.data()});
  on_host(texel.size(), InterpolateTexelTemperature{host_list, host_weight.data(), temperature.data(), host_T.data()});
  std::vector<float> host_wetting(texel.size(), 0.5f);
  const float contact = std::sqrt(2.0f) * s;
  std::vector<std::uint8_t> host_near(g.cell_count());
  on_host(host_near.size(), MarkCellsNearLiquid{liquid_set.host_view(), host_near.data()});
  on_host(texel.size(), RecordWetting{liquid_set.host_view(), host_near.data(), texel.data(), normal.data(), contact, 0.9f,
                                               host_wetting.data()});

  CudaExec::Buffer<Vec3> d_texel, d_normal;
  CudaExec::Buffer<float> d_volume, d_temperature, d_T, d_wetting, d_weight;
  CudaExec::upload(d_texel, texel);
  CudaExec::upload(d_normal, normal);
  CudaExec::upload(d_volume, volume);
  CudaExec::upload(d_temperature, temperature);
  CudaExec::upload(d_T, std::vector<float>(texel.size(), 1.0f));
  CudaExec::upload(d_wetting, std::vector<float>(texel.size(), 0.5f));
  NeighborListBuffers<CudaExec> device_lists;
  const NeighborList device_list = device_lists.build(gpu, d_texel, rigid_set.device_view(), kernel.h);
  d_weight.resize(device_lists.index.size());
  gpu.parallel_for(texel.size(), ComputeTexelWeights{device_list, CudaExec::ptr(d_texel), CudaExec::ptr(rigid_set.position),
                                                     CudaExec::ptr(d_volume), CudaExec::ptr(rigid_set.grid.order), first, count,
                                                     kernel, CudaExec::ptr(d_weight)});
  gpu.parallel_for(texel.size(), InterpolateTexelTemperature{device_list, CudaExec::ptr(d_weight), CudaExec::ptr(d_temperature),
                                                             CudaExec::ptr(d_T)});
  CudaExec::Buffer<std::uint8_t> d_near(g.cell_count());
  gpu.parallel_for(g.cell_count(), MarkCellsNearLiquid{liquid_set.device_view(), CudaExec::ptr(d_near)});
  EXPECT_EQ(CudaExec::download(d_near), host_near);
  gpu.parallel_for(texel.size(), RecordWetting{liquid_set.device_view(), CudaExec::ptr(d_near), CudaExec::ptr(d_texel), CudaExec::ptr(d_normal), contact, 0.9f,
                                               CudaExec::ptr(d_wetting)});
  gpu.synchronize();
  const std::vector<float> device_T = CudaExec::download(d_T), device_wetting = CudaExec::download(d_wetting);
  int interpolated = 0;
  for (std::size_t t = 0; t < texel.size(); ++t) {
    ASSERT_NEAR(device_T[t], host_T[t], 1e-4f * host_T[t]) << "texel " << t;
    ASSERT_EQ(device_wetting[t], host_wetting[t]) << "texel " << t;
    interpolated += host_T[t] != 1.0f;
  }
  EXPECT_GT(interpolated, 10000);
}

// The whole path through the simulation: static textures prepared on the
// GPU (neighbour lists, Eq. 7 weights, seeding), five steps, snapshots.
TEST_F(surface_CudaAgreement, SimulationTexturesMatchTheCpu) {
  const float s = 0.01f;
  SimulationSetup setup = test::plate_setup(s);
  setup.rigid_position = test::plate_particles(0.2f, 0.0f, s);
  for (const Vec3& x : setup.rigid_position) setup.rigid_temperature.push_back(280.0f + 300.0f * x.x * x.z);
  setup.heat_conduction = true;
  SurfaceTextureSetup tex;
  tex.rigid_count = setup.rigid_position.size();
  tex.texels = test::lattice_texels(150, 0.2f / 149, 0.0f);
  tex.initial_mass_per_area = 0.02f;
  setup.surfaces.push_back(tex);
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 5; ++k) {
      setup.liquid_position.push_back(Vec3{0.08f + i * s, s, 0.08f + k * s});
      setup.liquid_velocity.push_back(Vec3{});
    }
  auto cpu = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  auto gpu = make_simulation(ExecutionConfig{Device::Cuda, 0}, setup);
  for (int i = 0; i < 5; ++i) {
    cpu->step();
    gpu->step();
  }
  const SurfaceSnapshot a = cpu->surfaces().at(0), b = gpu->surfaces().at(0);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.mass_units, b.mass_units);
  std::size_t wetting_differs = 0;
  for (std::size_t t = 0; t < a.size(); ++t) {
    ASSERT_NEAR(a.temperature[t], b.temperature[t], 1e-4f * a.temperature[t]) << "texel " << t;
    wetting_differs += std::fabs(a.wetting[t] - b.wetting[t]) > 1e-6f;
  }
  // Contact is a threshold on positions that agree only to rounding.
  EXPECT_LE(wetting_differs, a.size() / 200);
}

}  // namespace
}  // namespace dp
