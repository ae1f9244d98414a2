// dewpoint-bench-coupling: per-step cost of Phase 3 (paper Alg. 1 lines
// 12-17) in the paper's Table 1 scene sizes: Drop (1207 liquid, 5108 rigid
// particles, 64^3 cells, 512^2 texels) and SCA Logo (135 liquid, 28K rigid,
// 1024^2 texels). Prints the medians of the step's Neigh, Heat and Eva
// timings (StepReport; Neigh and Heat include Phase 1's particle
// neighbourhoods and conduction, as the paper's columns do not say
// otherwise) and the same scene with the coupling switched off.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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
  int cells = 64;
  int steps = 10;
  std::string device = "cpu";
  int threads = 0;
};

Options parse(int argc, char** argv) {
  Options o;
  dp::bench::BenchArguments("dewpoint-bench-coupling")
      .add("--rigid-particles", "N", &o.rigid_particles)
      .add("--texels", "W", &o.texels)
      .add("--liquid", "N", &o.liquid)
      .add("--cells", "N", &o.cells)
      .add("--steps", "N", &o.steps)
      .add("--device", "cpu|cuda", &o.device)
      .add("--threads", "N", &o.threads)
      .parse(argc, argv);
  return o;
}

// A hot textured plate (150 degC, as in the paper's Drop) with a 20 degC
// liquid block on it, in air whose cells are just wider than 2 support radii.
dp::SimulationSetup drop_scene(const Options& o, bool coupled) {
  const float s = 0.005f;
  const float side = std::sqrt(static_cast<float>(o.rigid_particles)) * s;
  const float air_side = 2.05f * 2 * s * o.cells;  // cells of 2.05 support radii
  dp::SimulationSetup setup;
  setup.particle_spacing = s;
  setup.time_step.mode = dp::TimeStepMode::Fixed;
  setup.time_step.max_step = 1e-3f;
  const float c = 0.5f * side;
  setup.domain_min = dp::Vec3{c - 0.5f * air_side, -0.05f, c - 0.5f * air_side};
  setup.domain_max = dp::Vec3{c + 0.5f * air_side, air_side - 0.05f, c + 0.5f * air_side};
  std::vector<std::array<float, 3>> corners{{0, 0, 0}, {side, 0, 0}, {side, 0, side}, {0, 0, side}};
  setup.rigid_position = dp::sample_surface(corners, {{0, 2, 1}, {0, 3, 2}}, s);
  setup.rigid_temperature.assign(setup.rigid_position.size(), 423.15f);
  setup.rigid_held.assign(setup.rigid_position.size(), 1);
  const int n = static_cast<int>(std::cbrt(static_cast<double>(o.liquid)));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        setup.liquid_position.push_back(dp::Vec3{c + (i - n / 2) * s, 1.2f * s + j * s, c + (k - n / 2) * s});
        setup.liquid_velocity.push_back(dp::Vec3{});
      }
  dp::SurfaceTextureSetup t;
  t.rigid_count = setup.rigid_position.size();
  t.initial_mass_per_area = 0.01f;
  dp::TexelGeometry& g = t.texels;
  g.width = g.height = o.texels;
  const float step = side / o.texels;
  for (int r = 0; r < o.texels; ++r)
    for (int col = 0; col < o.texels; ++col) {
      g.pixel.push_back(static_cast<std::uint32_t>(r * o.texels + col));
      g.position.push_back(dp::Vec3{(col + 0.5f) * step, 0, (r + 0.5f) * step});
      g.normal.push_back(dp::Vec3{0, 1, 0});
      g.area.push_back(step * step);
      g.max_mass.push_back(0.05f * step * step);
    }
  setup.surfaces.push_back(t);
  dp::AirSettings a;
  a.domain_min = setup.domain_min;
  a.domain_max = setup.domain_max;
  a.resolution = o.cells;
  setup.air = a;
  setup.coupling.heat_exchange = setup.coupling.particle_evaporation = setup.coupling.texel_exchange = coupled;
  setup.coupling.particle_emission = coupled;
  return setup;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct Figures {
  double neigh_ms = 0, heat_ms = 0, eva_ms = 0, grid_ms = 0;
};

Figures run(const Options& o, bool coupled) {
  dp::ExecutionConfig exec{dp::parse_device(o.device), dp::resolve_thread_count(o.threads)};
  auto sim = dp::make_simulation(exec, drop_scene(o, coupled));
  sim->step();  // warm-up
  std::vector<double> neigh, heat, eva, grid;
  for (int i = 0; i < o.steps; ++i) {
    const dp::StepReport r = sim->step();
    neigh.push_back(1e3 * r.seconds_neighbours);
    heat.push_back(1e3 * r.seconds_heat);
    eva.push_back(1e3 * r.seconds_evaporation);
    grid.push_back(1e3 * r.seconds_grid);
  }
  const dp::WaterLedger l = sim->water_ledger();
  std::printf("  %s: %d steps, liquid -> air %.3e kg, texels -> air %.3e kg, emitted %.3e kg, ledger drift %.2e kg (%.2e relative)\n",
              coupled ? "coupled" : "uncoupled", o.steps + 1, l.liquid_to_air_kg, l.texels_to_air_kg, l.texels_to_liquid_kg,
              l.drift_kg(), l.relative_drift());
  return Figures{median(neigh), median(heat), median(eva), median(grid)};
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    std::printf("rigid ~%ld, texels %d^2, liquid ~%ld, cells %d^3, device %s, threads %d\n", o.rigid_particles, o.texels, o.liquid,
                o.cells, o.device.c_str(), dp::resolve_thread_count(o.threads));
    const Figures off = run(o, false), on = run(o, true);
    std::printf("median per step (ms)   Neigh   Heat    Eva    Grid\n");
    std::printf("coupling off          %6.2f %6.2f %6.2f %7.2f\n", off.neigh_ms, off.heat_ms, off.eva_ms, off.grid_ms);
    std::printf("coupling on           %6.2f %6.2f %6.2f %7.2f\n", on.neigh_ms, on.heat_ms, on.eva_ms, on.grid_ms);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dewpoint-bench-coupling: %s\n", e.what());
    return 2;
  }
  return 0;
}
