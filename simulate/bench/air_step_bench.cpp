// dewpoint-bench-air: time per step of the air phase (paper Sec. 4.2, Alg. 1
// lines 7-11) at a chosen resolution, as the simulation step reports it
// (StepReport::seconds_grid), with the projection's CG iterations. A humid,
// warm jet blows across a closed-bottom box with two open faces, past a small
// puddle on a plate, so every part of the air step works. Depends only on
// the simulator core, so it also runs on a bare CUDA machine.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench_arguments.h"
#include "simulation.h"

namespace {

struct Options {
  int resolution = 64;
  int steps = 30;
  int warmup = 10;
  std::string device = "cpu";
  int threads = 0;
  int fingerprint = 0;  // 1: print a hash of the air's fields after the run
  int parts = 0;        // 1: also the median time of each part of the step
  std::string cycle_layout = "backend";  // the pressure V-cycle's layout (cycle_layout_named)
};

Options parse(int argc, char** argv) {
  Options o;
  dp::bench::BenchArguments("dewpoint-bench-air")
      .add("--resolution", "N", &o.resolution)
      .add("--steps", "N", &o.steps)
      .add("--warmup", "N", &o.warmup)
      .add("--device", "cpu|cuda", &o.device)
      .add("--threads", "N", &o.threads)
      .add("--fingerprint", "0|1", &o.fingerprint)
      .add("--parts", "0|1", &o.parts)
      .add("--cycle-layout", "backend|separable|whole", &o.cycle_layout)
      .parse(argc, argv);
  return o;
}

// The V-cycle layout a --cycle-layout value names: the backend's own, the
// CPU's three separable passes per transfer with a launch per pass (the
// GPU's layout before one-pass transfers), or one pass per transfer
// without the one-block coarse levels. Same values in each; on one GPU they
// show what each part of the GPU's layout saves.
std::optional<dp::CycleLayout> cycle_layout_named(const std::string& name) {
  if (name == "backend") return std::nullopt;
  if (name == "separable") return dp::CycleLayout{false, 0};
  if (name == "whole") return dp::CycleLayout{true, 0};
  throw std::invalid_argument("--cycle-layout: expected backend, separable or whole, found '" + name + "'");
}

// A 1 m box of n^3 air cells; particles small enough that the cells exceed
// two support radii (cell = 5 spacings); a jet in from x = 0.
dp::SimulationSetup jet_box(int n, bool time_parts, std::optional<dp::CycleLayout> layout) {
  dp::SimulationSetup s;
  const float dx = 1.0f / n;
  s.particle_spacing = dx / 5;
  s.time_step.mode = dp::TimeStepMode::Fixed;
  s.time_step.max_step = 2e-3f;
  s.heat_conduction = false;
  s.domain_min = dp::Vec3{0, 0, 0};
  s.domain_max = dp::Vec3{1, 1, 1};
  const float h = s.particle_spacing;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 8; ++i) {
        s.liquid_position.push_back(dp::Vec3{0.6f + i * h, 0.1f + h + j * h, 0.5f + k * h});
        s.liquid_velocity.push_back(dp::Vec3{});
      }
  for (int k = -4; k < 12; ++k)
    for (int i = -4; i < 12; ++i) s.rigid_position.push_back(dp::Vec3{0.6f + i * h, 0.1f, 0.5f + k * h});
  dp::AirSettings a;
  a.domain_min = s.domain_min;
  a.domain_max = s.domain_max;
  a.resolution = n;
  a.ambient_vapor = 0.0086;  // 50 % relative humidity at 20 C
  a.vorticity_epsilon = 1.0f;
  a.time_parts = time_parts;
  a.cycle_layout = layout;
  a.open_face[static_cast<int>(dp::AirFace::XMax)] = true;
  a.open_face[static_cast<int>(dp::AirFace::YMax)] = true;
  dp::AirInflow jet;
  jet.shape = dp::AirInflow::Shape::Disc;
  jet.center = dp::Vec3{0.05f, 0.4f, 0.5f};
  jet.normal = dp::Vec3{1, 0, 0};
  jet.radius = 0.15f;
  jet.thickness = 0.05f;
  jet.velocity = dp::Vec3{1.0f, 0, 0};
  jet.temperature = 308.15f;
  jet.vapor = 0.035;
  a.inflows.push_back(jet);
  s.air = a;
  return s;
}

// FNV-1a over the bytes of the air's fields: an optimisation that claims to
// leave the arithmetic unchanged must leave this unchanged.
std::uint64_t fingerprint_of(const dp::AirSnapshot& a) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](const auto& values) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (std::size_t i = 0; i < values.size() * sizeof(values[0]); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  };
  mix(a.u);
  mix(a.v);
  mix(a.w);
  mix(a.temperature);
  mix(a.vapor);
  mix(a.kind);
  return h;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// The median of each part, in the step's order.
void print_parts(const std::vector<dp::AirStepSeconds>& steps) {
  const std::pair<const char*, double dp::AirStepSeconds::*> parts[] = {
      {"inflows", &dp::AirStepSeconds::inflows},     {"vapor", &dp::AirStepSeconds::vapor},
      {"temperature", &dp::AirStepSeconds::temperature}, {"forces", &dp::AirStepSeconds::forces},
      {"velocity", &dp::AirStepSeconds::velocity},   {"diffusion", &dp::AirStepSeconds::diffusion},
      {"projection", &dp::AirStepSeconds::projection}};
  std::printf("parts (ms, median):");
  for (const auto& [name, member] : parts) {
    std::vector<double> ms;
    for (const dp::AirStepSeconds& s : steps) ms.push_back(1e3 * (s.*member));
    std::printf(" %s %.2f", name, median(ms));
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    const dp::ExecutionConfig exec{dp::parse_device(o.device), dp::resolve_thread_count(o.threads)};
    auto sim = dp::make_simulation(exec, jet_box(o.resolution, o.parts != 0, cycle_layout_named(o.cycle_layout)));
    for (int i = 0; i < o.warmup; ++i) sim->step();
    std::vector<double> grid, iterations, residual;
    std::vector<dp::AirStepSeconds> parts;
    int substeps = 0;
    for (int i = 0; i < o.steps; ++i) {
      const dp::StepReport r = sim->step();
      grid.push_back(1e3 * r.seconds_grid);
      iterations.push_back(r.air.projection_iterations);
      residual.push_back(r.air.projection_residual);
      parts.push_back(r.air.seconds);
      substeps = std::max(substeps, r.air.advection_substeps);
    }
    // The mean as well: steps where liquid changed the cells also rebuild
    // the multigrid, which the median leaves out.
    const double mean = grid.empty() ? 0.0 : std::accumulate(grid.begin(), grid.end(), 0.0) / static_cast<double>(grid.size());
    std::printf("air %d^3 on %s (%d threads): %.2f ms/step (median of %d after %d warm-up; mean %.2f), CG %.0f iterations "
                "(median; max %.0f), residual %.1e, vapor sub-steps %d\n",
                o.resolution, sim->backend_name().c_str(), exec.threads, median(grid), o.steps, o.warmup, mean, median(iterations),
                *std::max_element(iterations.begin(), iterations.end()), median(residual), substeps);
    if (o.parts) print_parts(parts);
    if (o.fingerprint) std::printf("air fields fingerprint %016llx\n", static_cast<unsigned long long>(fingerprint_of(*sim->air())));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dewpoint-bench-air: %s\n", e.what());
    return 2;
  }
}
