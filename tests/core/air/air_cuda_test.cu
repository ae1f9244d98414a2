// The air step on the GPU against the CPU reference (label gpu; skipped, with
// the reason, where no GPU is present). Compiling this file is itself a
// check: every air functor must be valid device code.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../cuda_test_support.cuh"
#include "air_test_setups.h"
#include "air/air_grid.h"
#include "backend/cpu_exec.h"
#include "backend/cuda_exec.cuh"
#include "simulation.h"

namespace dp {
namespace {

class air_CudaAgreement : public test::RequiresGpu {};

AirSettings humid_box() {
  AirSettings s;
  s.domain_min = Vec3{0, 0, 0};
  s.domain_max = Vec3{0.64f, 0.64f, 0.64f};
  s.resolution = 24;
  s.ambient_vapor = 0.006;
  s.vorticity_epsilon = 2.0f;
  s.advection = AirAdvection::MacCormack;
  s.open_face[static_cast<int>(AirFace::XMax)] = true;
  s.open_face[static_cast<int>(AirFace::YMax)] = true;
  AirInflow in;
  in.shape = AirInflow::Shape::Disc;
  in.center = Vec3{0.05f, 0.3f, 0.32f};
  in.normal = Vec3{1, 0, 0};
  in.radius = 0.12f;
  in.thickness = 0.06f;
  in.velocity = Vec3{1.5f, 0, 0};
  in.temperature = 313.15f;
  in.vapor = 0.03;
  s.inflows.push_back(in);
  return s;
}

std::vector<Vec3> shell(Vec3 c, float r, int n) {
  std::vector<Vec3> p;
  const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < n; ++i) {
    const float y = 1.0f - 2.0f * (i + 0.5f) / n, rad = std::sqrt(1.0f - y * y), t = golden * i;
    p.push_back(c + r * Vec3{rad * std::cos(t), y, rad * std::sin(t)});
  }
  return p;
}

template <class T>
double max_difference(const std::vector<T>& a, const std::vector<T>& b, double* range) {
  double d = 0, r = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::fmax(d, std::fabs(static_cast<double>(a[i]) - static_cast<double>(b[i])));
    r = std::fmax(r, std::fabs(static_cast<double>(a[i])));
  }
  *range = r;
  return d;
}

// 20 steps of the whole air step around an obstacle, with an inflow and open
// faces: fields agree to float rounding grown over the steps (the GPU
// contracts multiply-adds), kinds exactly, the ledger to 1e-6.
TEST_F(air_CudaAgreement, TwentyAirStepsMatchTheCpu) {
  CudaExec gpu(0);
  CpuExec cpu(1);
  const AirSettings s = humid_box();
  UniformGrid g;
  g.origin = s.domain_min;
  g.cell_size = 0.04f;
  g.nx = g.ny = g.nz = 17;
  test::DeviceSet rigid;
  rigid.build(gpu, shell(Vec3{0.35f, 0.3f, 0.3f}, 0.12f, 4000), g);
  AirGrid<CudaExec> a(gpu, s, Vec3{0, -9.81f, 0}, rigid.device_view());
  AirGrid<CpuExec> b(cpu, s, Vec3{0, -9.81f, 0}, rigid.host_view());
  for (int n = 0; n < 20; ++n) {
    a.step(gpu, 0.01f);
    b.step(cpu, 0.01f);
  }
  const AirSnapshot x = a.snapshot(), y = b.snapshot();
  EXPECT_EQ(x.kind, y.kind);
  // The difference is taken before the range is read: the two operands of
  // one comparison are evaluated in no fixed order.
  double range;
  const double dvapor = max_difference(y.vapor, x.vapor, &range);
  EXPECT_GT(range, s.ambient_vapor);  // the inflow's humid air is there on the CPU
  EXPECT_LT(dvapor, 1e-4 * range);
  EXPECT_LT(max_difference(y.temperature, x.temperature, &range), 1e-3);  // K
  double ur, vr, wr;
  const double du = max_difference(y.u, x.u, &ur), dv = max_difference(y.v, x.v, &vr), dw = max_difference(y.w, x.w, &wr);
  const double umax = std::fmax(ur, std::fmax(vr, wr));
  RecordProperty("max_velocity_difference", std::to_string(std::fmax(du, std::fmax(dv, dw)) / umax));
  EXPECT_LT(std::fmax(du, std::fmax(dv, dw)), 1e-3 * umax);
  EXPECT_NEAR(x.ledger.inflow_gain, y.ledger.inflow_gain, 1e-6 * std::fabs(y.ledger.inflow_gain));
  EXPECT_NEAR(x.ledger.open_out, y.ledger.open_out, 1e-6 * std::fabs(y.ledger.open_out) + 1e-15);
  EXPECT_NEAR(x.vapor_mass(), x.ledger.expected_mass(), 1e-9 * x.vapor_mass());
}

// One V-cycle (z = M^-1 r) on the GPU against the CPU's, on a grid with
// obstacles and an open face whose levels hold 47520, 6120, 810 and 125
// cells, in every layout of its passes (CycleLayout): the GPU's own (one
// pass per transfer, the levels from 810 cells down in one thread block),
// the CPU's separable passes with a launch each, and the whole cycle in one
// block. The GPU contracts multiply-adds, so z agrees to float rounding,
// not bit for bit.
TEST_F(air_CudaAgreement, VCycleMatchesTheCpuInEveryLayout) {
  CudaExec gpu(0);
  CpuExec cpu(1);
  const test::PoissonProblem p = test::random_poisson_problem(61);
  const std::vector<float> z_cpu = test::one_v_cycle(cpu, p, CycleLayout{});
  double zmax = 0;
  for (float v : z_cpu) zmax = std::fmax(zmax, std::fabs(v));
  ASSERT_GT(zmax, 0.01);
  const CycleLayout gpus_own{CudaExec::kPassCostsALaunch, CudaExec::kOneBlockElements};
  for (const CycleLayout layout : {gpus_own, CycleLayout{false, 0}, CycleLayout{true, p.cells()}}) {
    const std::vector<float> z = test::one_v_cycle(gpu, p, layout);
    double difference = 0;
    for (std::size_t c = 0; c < p.cells(); ++c) difference = std::fmax(difference, std::fabs(static_cast<double>(z[c]) - z_cpu[c]));
    EXPECT_LT(difference, 1e-5 * zmax) << "whole transfers " << layout.whole_transfers << ", one block from "
                                       << layout.one_block_cells << " cells";
  }
}

// The whole simulation with an air phase, on both backends.
TEST_F(air_CudaAgreement, SimulationWithAirMatchesTheCpu) {
  SimulationSetup setup;
  setup.particle_spacing = 0.01f;
  setup.time_step.mode = TimeStepMode::Fixed;
  setup.time_step.max_step = 1e-3f;
  setup.domain_min = Vec3{-0.2f, -0.05f, -0.2f};
  setup.domain_max = Vec3{0.2f, 0.4f, 0.2f};
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 10; ++i) {
        setup.liquid_position.push_back(Vec3{(i - 5) * 0.01f, 0.02f + j * 0.01f, (k - 5) * 0.01f});
        setup.liquid_velocity.push_back(Vec3{});
      }
  for (int k = -12; k <= 12; ++k)
    for (int i = -12; i <= 12; ++i) setup.rigid_position.push_back(Vec3{i * 0.01f, 0.0f, k * 0.01f});
  AirSettings air;
  air.domain_min = setup.domain_min;
  air.domain_max = setup.domain_max;
  air.resolution = 9;
  air.open_face[static_cast<int>(AirFace::YMax)] = true;
  setup.air = air;
  auto c = make_simulation(ExecutionConfig{Device::Cpu, 1}, setup);
  auto d = make_simulation(ExecutionConfig{Device::Cuda, 0}, setup);
  for (int n = 0; n < 10; ++n) {
    c->step();
    d->step();
  }
  const AirSnapshot x = *c->air(), y = *d->air();
  EXPECT_EQ(x.kind, y.kind);
  double range;
  EXPECT_LT(max_difference(x.temperature, y.temperature, &range), 1e-3);
  EXPECT_GT(d->last_step().seconds_grid, 0.0);
}

}  // namespace
}  // namespace dp
