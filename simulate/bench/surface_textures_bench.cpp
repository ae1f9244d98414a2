// dewpoint-bench-surface: cost of the rigid-surface textures (paper Sec. 4.3,
// 4.4, 5.2) on a plate the size of the paper's scenes (Table 1: Drop, 5108
// rigid particles and 512^2 texels; SCA Logo, 28K and 1024^2): the one-off
// set-up (texel <-> rigid neighbourhoods, Poisson-disk seeding) and, per
// step, Eq. 7 plus the wetting history, as the difference between the step's
// heat phase with and without textures. Depends only on the simulator core.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "rigid/sample_surface.h"
#include "bench_arguments.h"
#include "simulation.h"

namespace {

struct Options {
  long rigid_particles = 5108;
  int texels = 512;
  long liquid = 1207;
  int steps = 20;
  std::string device = "cpu";
  int threads = 0;
};

Options parse(int argc, char** argv) {
  Options o;
  dp::bench::BenchArguments("dewpoint-bench-surface")
      .add("--rigid-particles", "N", &o.rigid_particles)
      .add("--texels", "W", &o.texels)
      .add("--liquid", "N", &o.liquid)
      .add("--steps", "N", &o.steps)
      .add("--device", "cpu|cuda", &o.device)
      .add("--threads", "N", &o.threads)
      .parse(argc, argv);
  return o;
}

// A square plate at y = 0 of about the requested particle count at 5 mm
// spacing, a W x W texel atlas over it, and a liquid block resting on it.
dp::SimulationSetup plate_scene(const Options& o, bool textured) {
  const float s = 0.005f;
  const float side = std::sqrt(static_cast<float>(o.rigid_particles)) * s;
  dp::SimulationSetup setup;
  setup.particle_spacing = s;
  setup.domain_min = dp::Vec3{-0.05f, -0.05f, -0.05f};
  setup.domain_max = dp::Vec3{side + 0.05f, 0.3f, side + 0.05f};
  std::vector<std::array<float, 3>> corners{{0, 0, 0}, {side, 0, 0}, {side, 0, side}, {0, 0, side}};
  setup.rigid_position = dp::sample_surface(corners, {{0, 2, 1}, {0, 3, 2}}, s);
  setup.rigid_temperature.resize(setup.rigid_position.size());
  for (std::size_t k = 0; k < setup.rigid_position.size(); ++k) setup.rigid_temperature[k] = 280 + 100 * setup.rigid_position[k].x;
  const int n = static_cast<int>(std::cbrt(static_cast<double>(o.liquid)));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        setup.liquid_position.push_back(dp::Vec3{0.5f * side + (i - n / 2) * s, 1.2f * s + j * s, 0.5f * side + (k - n / 2) * s});
        setup.liquid_velocity.push_back(dp::Vec3{});
      }
  if (!textured) return setup;
  dp::SurfaceTextureSetup t;
  t.rigid_count = setup.rigid_position.size();
  dp::TexelGeometry& g = t.texels;
  g.width = g.height = o.texels;
  const float step = side / o.texels;
  for (int r = 0; r < o.texels; ++r)
    for (int c = 0; c < o.texels; ++c) {
      g.pixel.push_back(static_cast<std::uint32_t>(r * o.texels + c));
      g.position.push_back(dp::Vec3{(c + 0.5f) * step, 0, (r + 0.5f) * step});
      g.normal.push_back(dp::Vec3{0, 1, 0});
      g.area.push_back(step * step);
      g.max_mass.push_back(0.05f * step * step);
    }
  setup.surfaces.push_back(t);
  return setup;
}

struct Figures {
  double construct_s = 0, heat_ms = 0, step_ms = 0;
  double cpu_ms_per_step = 0;  // process CPU time: on a shared machine, what the steps cost rather than how long they waited
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

Figures run(const Options& o, bool textured) {
  dp::ExecutionConfig exec{dp::parse_device(o.device), dp::resolve_thread_count(o.threads)};
  const dp::SimulationSetup setup = plate_scene(o, textured);
  auto t0 = std::chrono::steady_clock::now();
  auto sim = dp::make_simulation(exec, setup);
  Figures f;
  f.construct_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sim->step();  // warm-up
  std::vector<double> heat, total;
  const std::clock_t c0 = std::clock();
  for (int i = 0; i < o.steps; ++i) {
    const dp::StepReport r = sim->step();
    heat.push_back(1e3 * r.seconds_heat);
    total.push_back(1e3 * (r.seconds_neighbours + r.seconds_pressure + r.seconds_heat + r.seconds_other));
  }
  f.cpu_ms_per_step = 1e3 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / o.steps;
  f.heat_ms = median(heat);
  f.step_ms = median(total);
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    const Figures plain = run(o, false), textured = run(o, true);
    std::printf("rigid particles ~%ld, texels %d^2, liquid ~%ld, device %s, threads %d\n", o.rigid_particles, o.texels, o.liquid,
                o.device.c_str(), dp::resolve_thread_count(o.threads));
    std::printf("set-up (make_simulation): %.3f s without textures, %.3f s with (texel neighbourhoods, seeding)\n",
                plain.construct_s, textured.construct_s);
    std::printf("heat phase per step (median of %d): %.2f ms without textures, %.2f ms with: textures %.2f ms (Eq. 7 + wetting)\n",
                o.steps, plain.heat_ms, textured.heat_ms, textured.heat_ms - plain.heat_ms);
    std::printf("whole step: %.2f ms without, %.2f ms with\n", plain.step_ms, textured.step_ms);
    std::printf("CPU time per step, all threads: %.2f ms without, %.2f ms with: textures %.2f ms\n", plain.cpu_ms_per_step,
                textured.cpu_ms_per_step, textured.cpu_ms_per_step - plain.cpu_ms_per_step);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dewpoint-bench-surface: %s\n", e.what());
    return 2;
  }
  return 0;
}
