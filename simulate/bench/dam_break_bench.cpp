// dewpoint-bench-dam-break: time per step of the liquid simulation on a dam
// break of a chosen size, split as the step reports it (neighbour search,
// pressure solve, heat, the rest), with the pressure solver's iterations, for
// PCISPH or DFSPH; the timed window starts after a number of steps or at a
// simulated time, to compare early and late in the collapse. Depends only on
// the simulator core, so it also runs on a bare CUDA machine.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "bench_arguments.h"
#include "simulation.h"

namespace {

struct Options {
  long particles = 100000;
  int steps = 20;
  int warmup = 5;
  double warmup_until = 0;  // s of simulated time, after the warm-up steps
  std::string method = "pcisph";
  int warm_start = 0;
  std::string device = "cpu";
  int threads = 0;
};

Options parse(int argc, char** argv) {
  Options o;
  dp::bench::BenchArguments("dewpoint-bench-dam-break")
      .add("--particles", "N", &o.particles)
      .add("--steps", "N", &o.steps)
      .add("--warmup", "N", &o.warmup)
      .add("--warmup-until", "SECONDS", &o.warmup_until)
      .add("--method", "pcisph|dfsph", &o.method)
      .add("--warm-start", "0|1", &o.warm_start)
      .add("--device", "cpu|cuda", &o.device)
      .add("--threads", "N", &o.threads)
      .parse(argc, argv);
  return o;
}

// A column of width a, height 2a and depth a/2 in a tank 4a long, at the
// spacing that gives about the requested particle count.
dp::SimulationSetup dam_break(long particles) {
  const float a = 1.0f;
  const float s = std::cbrt(a * 2 * a * 0.5f * a / static_cast<float>(particles));
  dp::SimulationSetup setup;
  setup.particle_spacing = s;
  setup.liquid.xsph_epsilon = 0.01f;
  setup.liquid.boundary_friction = 0.1f;
  const int nx = static_cast<int>(a / s), ny = static_cast<int>(2 * a / s), nz = static_cast<int>(0.5f * a / s);
  const float gap = 1.2f * s, lx = 4 * a, ly = 2.5f * a, lz = (nz - 1) * s + 2 * gap;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        setup.liquid_position.push_back(dp::Vec3{gap + i * s, gap + j * s, gap + k * s});
        setup.liquid_velocity.push_back(dp::Vec3{});
      }
  const int mx = static_cast<int>(std::ceil(lx / s)), my = static_cast<int>(std::ceil(ly / s)), mz = static_cast<int>(std::ceil(lz / s));
  const float dx = lx / mx, dy = ly / my, dz = lz / mz;
  for (int k = 0; k <= mz; ++k)
    for (int i = 0; i <= mx; ++i) setup.rigid_position.push_back(dp::Vec3{i * dx, 0, k * dz});
  for (int j = 1; j <= my; ++j) {
    for (int i = 0; i <= mx; ++i) {
      setup.rigid_position.push_back(dp::Vec3{i * dx, j * dy, 0});
      setup.rigid_position.push_back(dp::Vec3{i * dx, j * dy, lz});
    }
    for (int k = 1; k < mz; ++k) {
      setup.rigid_position.push_back(dp::Vec3{0, j * dy, k * dz});
      setup.rigid_position.push_back(dp::Vec3{lx, j * dy, k * dz});
    }
  }
  setup.domain_min = dp::Vec3{-0.1f, -0.1f, -0.1f};
  setup.domain_max = dp::Vec3{lx + 0.1f, ly + 0.5f, lz + 0.1f};
  return setup;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  Options o = parse(argc, argv);
  dp::SimulationSetup setup = dam_break(o.particles);
  if (o.method != "pcisph" && o.method != "dfsph") {
    std::fprintf(stderr, "dewpoint-bench-dam-break: --method: expected pcisph or dfsph, found '%s'\n", o.method.c_str());
    return 2;
  }
  setup.pressure.method = o.method == "dfsph" ? dp::PressureSolverMethod::Dfsph : dp::PressureSolverMethod::Pcisph;
  setup.pressure.warm_start = o.warm_start != 0;
  try {
    dp::ExecutionConfig exec{dp::parse_device(o.device), dp::resolve_thread_count(o.threads)};
    auto sim = dp::make_simulation(exec, setup);
    const auto warmup_start = std::chrono::steady_clock::now();
    for (int i = 0; i < o.warmup; ++i) sim->step();
    while (sim->time() < o.warmup_until) sim->step();
    const double warmup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - warmup_start).count();
    const double window_start = sim->time();
    const std::int64_t first_timed_step = sim->step_count() + 1;
    std::vector<double> total, neighbours, pressure, heat, other, iterations, divergence_iterations, density_error;
    for (int i = 0; i < o.steps; ++i) {
      auto t = std::chrono::steady_clock::now();
      dp::StepReport r = sim->step();
      total.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count() * 1e3);
      neighbours.push_back(r.seconds_neighbours * 1e3);
      pressure.push_back(r.seconds_pressure * 1e3);
      heat.push_back(r.seconds_heat * 1e3);
      other.push_back(r.seconds_other * 1e3);
      iterations.push_back(r.pressure_iterations);
      divergence_iterations.push_back(r.divergence_iterations);
      density_error.push_back(r.density_error);
    }
    const double window = sim->time() - window_start;
    std::printf("dam break: %zu liquid + %zu rigid particles, spacing %.4g m, %s%s, device %s, %d threads\n",
                setup.liquid_position.size(), setup.rigid_position.size(), setup.particle_spacing, o.method.c_str(),
                setup.pressure.warm_start ? " warm-started" : "", o.device.c_str(), exec.threads);
    std::printf("warm-up: steps 1-%lld, t = 0-%.4f s, %.1f s wall\n", static_cast<long long>(first_timed_step - 1),
                window_start, warmup_seconds);
    std::printf("timed steps %lld-%lld, t = %.4f-%.4f s, mean dt %.3g ms\n", static_cast<long long>(first_timed_step),
                static_cast<long long>(sim->step_count()), window_start, sim->time(), window / o.steps * 1e3);
    std::printf("median ms/step: total %.2f | neighbours %.2f | pressure %.2f (iterations %.0f, divergence %.0f) | heat %.2f | other %.2f\n",
                median(total), median(neighbours), median(pressure), median(iterations), median(divergence_iterations),
                median(heat), median(other));
    std::printf("median density error after the solve: %.3g %%\n", median(density_error) * 100);
    std::printf("wall s per simulated s over the window: %.1f\n",
                std::accumulate(total.begin(), total.end(), 0.0) * 1e-3 / window);
    std::printf("median ns per liquid particle-step: %.1f\n", median(total) * 1e6 / static_cast<double>(setup.liquid_position.size()));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dewpoint-bench-dam-break: %s\n", e.what());
    return 2;
  }
  return 0;
}
