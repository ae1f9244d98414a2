// dewpoint-simulate: runs a scene's simulation and writes its frames.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "air_vdb.h"
#include "checkpoint_folder.h"
#include "cli_common.h"
#include "dewpoint/version.h"
#include "paraview_series.h"
#include "frames.h"
#include "ledger_csv.h"
#include "log_options.h"
#include "scene.h"
#include "simulation.h"
#include "simulation_setup.h"
#include "step_timings.h"
#include "surface_frames.h"

namespace fs = std::filesystem;

namespace {

struct Options {
  fs::path scene;
  fs::path out;
  std::string device = "cpu";
  int threads = 0;
  std::string frames;
  std::string preset;
  double duration_s = 0;  // > 0: replaces simulation.duration_s
  dp::io::LogOptions log;
  dp::io::LogLevel level = dp::io::LogLevel::Info;  // log.effective(), once parsed
  bool resume = false;
  int checkpoint_every = 10;  // frames; 0: none
  bool paraview = false;      // also the frames as VTK files and their collection
};

const char* const kParaViewCollection = "shot.pvd";

// simulation.settle, before frame 0: the frames and the clock start from the
// settled liquid.
void settle_liquid(dp::Simulation& simulation, const dp::SettleSettings& settle, dp::io::LogLevel level) {
  std::int64_t steps = 0;
  int halvings = 0;
  dp::StepReport last;
  simulation.settle([&](const dp::StepReport& report) {
    ++steps;
    halvings += report.pressure_halvings;
    last = report;
    if (dp::io::logs(level, dp::io::LogLevel::Debug))
      std::cerr << "dewpoint-simulate: settling step " << steps << ": dt=" << report.dt << " s  pressure solve "
                << report.pressure_iterations << " it, density error " << 100.0 * report.density_error << " %\n";
  });
  if (dp::io::logs(level, dp::io::LogLevel::Info))
    std::cerr << "dewpoint-simulate: settled the liquid for " << settle.duration << " s in " << steps << " steps (last dt "
              << last.dt << " s, " << halvings << " halved for the pressure solve); velocities set to zero at t = 0\n";
}

// The newest intact checkpoint of OUT, checked against the scene; none when
// there is none (the run then starts at frame 0). Damaged ones are skipped
// with a warning; a checkpoint of another scene is an error.
std::optional<dp::io::Checkpoint> checkpoint_to_resume(const fs::path& dir, const dp::io::Scene& scene, dp::io::LogLevel level) {
  const bool warn = dp::io::logs(level, dp::io::LogLevel::Warn);
  dp::io::NewestCheckpoint found = dp::io::find_newest_checkpoint(dir);
  for (const std::string& why : found.skipped)
    if (warn) std::cerr << "dewpoint-simulate: warning: skipping checkpoint " << why << "\n";
  if (!found.checkpoint) {
    if (warn)
      std::cerr << "dewpoint-simulate: warning: --resume: no usable checkpoint in " << dir.string()
                << "; starting from the beginning\n";
    return std::nullopt;
  }
  if (found.checkpoint->scene_hash != dp::io::scene_document_hash(scene.document))
    throw std::invalid_argument(found.file.string() + ": --resume: " + scene.file.string() +
                                " has changed since this checkpoint was written; run without --resume to start over");
  return found.checkpoint;
}

// The frames an interrupted run listed up to `last_frame`; none when it
// left no manifest.
std::vector<dp::io::FrameEntry> frames_through(const fs::path& frames_dir, int last_frame) {
  std::vector<dp::io::FrameEntry> kept;
  if (!fs::exists(frames_dir / "manifest.json")) return kept;
  for (const dp::io::FrameEntry& f : dp::io::read_manifest(frames_dir).frames)
    if (f.index <= last_frame) kept.push_back(f);
  return kept;
}

int run(const Options& opt) {
  // Everything that can be wrong with the input is found before any output
  // exists: scene, meshes, frame range, device.
  dp::io::Scene scene = dp::io::load_scene(opt.scene, opt.preset);
  std::vector<dp::io::RigidAtlas> atlases;
  dp::SimulationSetup setup = dp::io::make_simulation_setup(scene, &atlases);
  dp::io::FrameRange range = opt.frames.empty() ? dp::io::FrameRange{} : dp::io::parse_frame_range(opt.frames);
  dp::ExecutionConfig exec{dp::parse_device(opt.device), dp::resolve_thread_count(opt.threads)};

  // The duration decides only where the shot ends (the physics never reads
  // it), so a run of another length resumes from the same checkpoints.
  if (opt.duration_s > 0) scene.simulation.duration_s = opt.duration_s;
  const auto& sim = scene.simulation;
  const int last_frame_of_scene = static_cast<int>(std::floor(sim.duration_s * sim.frame_rate_hz + 1e-9));
  const int last_frame = range.last < 0 ? last_frame_of_scene : std::min(range.last, last_frame_of_scene);
  if (range.first > last_frame)
    throw std::invalid_argument("--frames: first frame " + std::to_string(range.first) + " is past the scene's last frame " +
                                std::to_string(last_frame_of_scene));
  // Without liquid only textures can hold water (the paper's texture-only SCA Logo Tex).
  if (setup.liquid_position.empty() && setup.surfaces.empty())
    throw dp::io::SceneError(scene.file.string() + ": simulation.liquid_blocks: no liquid particles and no textured rigid");

  std::unique_ptr<dp::Simulation> simulation = dp::make_simulation(exec, setup);
  const fs::path checkpoints_dir = opt.out / "checkpoints";
  std::optional<dp::io::Checkpoint> resumed = opt.resume ? checkpoint_to_resume(checkpoints_dir, scene, opt.level) : std::nullopt;
  if (resumed) {
    simulation->restore(resumed->state);
    if (dp::io::logs(opt.level, dp::io::LogLevel::Info)) std::cerr << "dewpoint-simulate: resuming after frame " << resumed->frame << " (step " << resumed->state.steps << ")\n";
  }
  const int first_frame = resumed ? resumed->frame + 1 : 0;

  const fs::path frames_dir = opt.out / "frames";
  fs::create_directories(frames_dir);

  const std::string comment = std::string("dewpoint-simulate ") + dp::kVersion + " scene " + scene.file.string();
  dp::io::FramesManifest manifest;
  manifest.scene_file = scene.file;
  manifest.scene_name = scene.name;
  manifest.particle_spacing_m = sim.particle_spacing_m;
  manifest.particle_radius_m = 0.5 * sim.particle_spacing_m;
  manifest.rigid_particles_file = "rigid_particles.ply";
  manifest.extra["generator"] = std::string("dewpoint-simulate ") + dp::kVersion;
  manifest.extra["settings"] = {{"device", opt.device}, {"threads", exec.threads}, {"frames", opt.frames}};
  if (opt.paraview) manifest.extra["settings"]["paraview"] = true;
  if (opt.duration_s > 0) manifest.extra["settings"]["duration_s"] = opt.duration_s;
  if (exec.device == dp::Device::Cpu) manifest.extra["settings"]["cpu_isa"] = dp::cpu_isa_name(exec.cpu_isa);
  if (resumed) {
    manifest.extra["settings"]["resumed_after_frame"] = resumed->frame;
    manifest.frames = frames_through(frames_dir, resumed->frame);
  }
  manifest.extra["scene"] = scene.document;
  if (!scene.preset.empty()) manifest.extra["preset"] = scene.preset;
  dp::io::write_rigid_particles(frames_dir / manifest.rigid_particles_file, simulation->rigid_particles(),
                                simulation->rigid_volumes(), simulation->rigid_temperatures(), comment);
  for (std::size_t r = 0; r < atlases.size(); ++r) {
    const std::string& name = atlases[r].rigid_name;
    manifest.rigids.push_back({name, "rigid_" + name + ".ply", {setup.surfaces[r].texels.width, setup.surfaces[r].texels.height}});
    dp::io::write_rigid_atlas_mesh(frames_dir / manifest.rigids.back().mesh_file, atlases[r].mesh, comment);
  }

  // A run that starts over owns the folder from here on (its manifest and
  // timings start again): an earlier run's checkpoints would outrank this
  // run's own (only the newest two stay), and a --resume would continue the
  // earlier run over this one's frames.
  if (!resumed) dp::io::remove_checkpoints(checkpoints_dir);

  // Table-1 timings of every step (docs/file-formats.md, stats folder).
  const fs::path stats_dir = opt.out / "stats";
  fs::create_directories(stats_dir);
  dp::io::StepTimingsCsv timings = resumed ? dp::io::StepTimingsCsv(stats_dir / "timings.csv", resumed->state.steps)
                                           : dp::io::StepTimingsCsv(stats_dir / "timings.csv");
  // Before the progress clock starts: its steps per second are the run's.
  if (!resumed && setup.settle.duration > 0) settle_liquid(*simulation, setup.settle, opt.level);

  const double frame_interval = 1.0 / sim.frame_rate_hz;
  dp::io::Progress progress("simulate " + scene.name, last_frame + 1, !dp::io::logs(opt.level, dp::io::LogLevel::Info));
  const auto run_start = std::chrono::steady_clock::now();
  const std::int64_t first_step = simulation->step_count();
  int frames_done = first_frame;  // frames whose time the simulation has reached
  // The ParaView collection lists every frame with its files, those of a
  // resumed run's earlier frames included.
  std::vector<dp::io::SeriesFrame> series;
  const auto series_files = [](int frame) {
    return std::pair{dp::io::frame_file_name("particles", frame, "vtp"), dp::io::frame_file_name("air", frame, "vti")};
  };
  if (opt.paraview)
    for (const dp::io::FrameEntry& e : manifest.frames) {
      const auto [particles_file, air_file] = series_files(e.index);
      if (fs::exists(frames_dir / particles_file))
        series.push_back({e.time_s, particles_file, fs::exists(frames_dir / air_file) ? air_file : std::string()});
    }
  // One frame's files and its manifest entry; the manifest is rewritten
  // last, so that it lists only complete frames.
  auto write_frame = [&](int frame) {
    dp::ParticleSnapshot particles = simulation->particles();
    dp::io::FrameEntry entry;
    entry.index = frame;
    entry.time_s = simulation->time();
    entry.step = simulation->step_count();
    entry.liquid_particles = particles.size();
    entry.particles_file = dp::io::frame_file_name("particles", frame, "ply");
    dp::io::write_particle_frame(frames_dir / entry.particles_file, particles,
                                 static_cast<float>(manifest.particle_radius_m), comment);
    const std::vector<dp::SurfaceSnapshot> surfaces = simulation->surfaces();
    for (std::size_t r = 0; r < surfaces.size(); ++r) {
      const std::string file = dp::io::frame_file_name("surface_" + atlases[r].rigid_name, frame, "exr");
      dp::io::write_surface_frame(frames_dir / file, surfaces[r]);
      entry.surface_files[atlases[r].rigid_name] = file;
    }
    // One download of the air for every file that shows it.
    const std::optional<dp::AirSnapshot> air = simulation->air();
    if (air) {
      entry.air_file = dp::io::frame_file_name("air", frame, "vdb");
      dp::io::write_air_frame(frames_dir / entry.air_file, *air, comment);
      const dp::AirLedger& l = air->ledger;
      entry.air_vapor = {{"mass_kg", air->vapor_mass()}, {"initial_kg", l.initial}, {"inflow_gain_kg", l.inflow_gain},
                         {"open_in_kg", l.open_in}, {"open_out_kg", l.open_out}, {"exchanged_kg", l.exchanged}};
    }
    const dp::WaterLedger w = simulation->water_ledger();
    entry.water = {{"liquid_kg", w.liquid_kg},         {"texels_kg", w.texel_kg},
                   {"vapor_kg", w.vapor_kg},           {"initial_kg", w.initial_kg},
                   {"inflow_gain_kg", w.inflow_gain_kg}, {"open_in_kg", w.open_in_kg},
                   {"open_out_kg", w.open_out_kg},     {"liquid_to_air_kg", w.liquid_to_air_kg},
                   {"texels_to_air_kg", w.texels_to_air_kg}, {"texels_to_liquid_kg", w.texels_to_liquid_kg},
                   {"liquid_out_kg", w.liquid_out_kg},
                   {"drift_kg", w.drift_kg()},
                   {"relative_drift", w.relative_drift()}};
    if (opt.paraview) {
      const auto [particles_file, air_file] = series_files(frame);
      dp::io::write_particles_vtp(frames_dir / particles_file, particles, static_cast<float>(manifest.particle_radius_m));
      if (air) dp::io::write_air_vti(frames_dir / air_file, *air);
      series.push_back({entry.time_s, particles_file, air ? air_file : std::string()});
      dp::io::write_pvd(frames_dir / kParaViewCollection, series);
    }
    manifest.frames.push_back(entry);
    dp::io::write_manifest(frames_dir, manifest);
    dp::io::write_ledger_csv(stats_dir / "ledger.csv", manifest.frames);
  };
  auto progress_detail = [&]() {
    const dp::StepReport& last = simulation->last_step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
    const double steps_per_s = seconds > 0 ? static_cast<double>(simulation->step_count() - first_step) / seconds : 0.0;
    // The solver's part: PCISPH's iterations, or DFSPH's two solves'.
    char solver[64];
    if (setup.pressure.method == dp::PressureSolverMethod::Dfsph)
      std::snprintf(solver, sizeof solver, "DFSPH divergence %d it, density %d it", last.divergence_iterations,
                    last.pressure_iterations);
    else
      std::snprintf(solver, sizeof solver, "PCISPH %d it", last.pressure_iterations);
    char detail[240];
    std::snprintf(detail, sizeof detail, "t=%.4f s  step %lld (%.1f steps/s)  dt=%.2e s  %s, density error %.3f %%",
                  simulation->time(), static_cast<long long>(simulation->step_count()), steps_per_s, last.dt, solver,
                  100.0 * last.density_error);
    std::string line = detail;
    if (dp::io::logs(opt.level, dp::io::LogLevel::Debug)) line += std::string("  (dt set by ") + last.limited_by + ")";
    if (setup.air) {
      char air[96];
      std::snprintf(air, sizeof air, "  air CG %d it, residual %.1e", last.air.projection_iterations,
                    static_cast<double>(last.air.projection_residual));
      line += air;
    }
    return line;
  };
  // Every step: its timings row; the terminal's progress line when due; at debug, a line of its own.
  auto record_step = [&](const dp::StepReport& report) {
    timings.add(dp::io::table1_row(report, simulation->step_count(), simulation->time()));
    if (dp::io::logs(opt.level, dp::io::LogLevel::Debug))
      std::cerr << "dewpoint-simulate: step " << simulation->step_count() << ": " << progress_detail() << "\n";
    if (report.particles_left_domain > 0 && dp::io::logs(opt.level, dp::io::LogLevel::Info))
      std::cerr << "dewpoint-simulate: step " << simulation->step_count() << ": " << report.particles_left_domain
                << " liquid particle(s) left the domain and were removed (" << simulation->water_ledger().liquid_out_kg * 1e3
                << " g so far, in the ledger's liquid_out_kg)\n";
    if (progress.due(frames_done)) progress.update(frames_done, progress_detail());
  };

  const std::uint64_t scene_hash = dp::io::scene_document_hash(scene.document);
  for (int frame = first_frame; frame <= last_frame; ++frame) {
    // Frame times are independent of the step size: step until the frame's time.
    const double frame_time = frame * frame_interval;
    simulation->advance_to(frame_time, record_step);
    timings.flush();
    if (range.contains(frame)) write_frame(frame);
    // After the frame's files: a run resumed from here has them all.
    if (opt.checkpoint_every > 0 && frame > 0 && frame % opt.checkpoint_every == 0 && frame < last_frame)
      dp::io::save_checkpoint(checkpoints_dir, dp::io::Checkpoint{frame, scene_hash, simulation->state()});
    frames_done = frame + 1;
    progress.update(frames_done, progress_detail());
  }
  progress.finish(std::to_string(manifest.frames.size()) + " frames in " + frames_dir.string());
  const dp::io::TimingSummary summary = timings.summary();
  dp::io::write_timing_summary(stats_dir / "timings_summary.json", summary);
  if (dp::io::logs(opt.level, dp::io::LogLevel::Info)) std::cout << dp::io::format_timing_summary(summary);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dewpoint-simulate: simulates a scene's liquid and writes per-frame particles and a manifest"};
  app.set_version_flag("--version", std::string("dewpoint-simulate ") + dp::kVersion);
  Options opt;
  app.add_option("scene", opt.scene, "scene file (JSON)")->required();
  app.add_option("-o,--output", opt.out, "output folder of the shot; frames go to OUT/frames")->required();
  app.add_option("--device", opt.device, "cpu or cuda")->check(CLI::IsMember({"cpu", "cuda"}));
  app.add_option("--threads", opt.threads, "CPU threads (0: all)")->check(CLI::NonNegativeNumber);
  app.add_option("--frames", opt.frames, "frames to write, A-B (inclusive)");
  app.add_option("--preset", opt.preset, "apply the scene's presets.NAME (a JSON merge patch, e.g. preview)");
  app.add_option("--duration", opt.duration_s,
                 "simulated seconds of the shot, replacing simulation.duration_s (e.g. a table1 preset run for a whole second)")
      ->check(CLI::PositiveNumber);
  dp::io::add_log_options(app, opt.log);
  app.add_flag("--paraview", opt.paraview,
               "also write each frame as VTK files and OUT/frames/shot.pvd, a time series ParaView opens (docs/file-formats.md)");
  app.add_flag("--resume", opt.resume,
               "continue an interrupted run from the newest intact checkpoint in OUT/checkpoints (from the start when there is none)");
  app.add_option("--checkpoint-every", opt.checkpoint_every,
                 "write a checkpoint every N frames to OUT/checkpoints, keeping the last two (0: none; default 10)")
      ->check(CLI::NonNegativeNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; any bad command line exits 2 like bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    opt.level = opt.log.effective();
    return run(opt);
  } catch (const dp::InstabilityError& e) {
    std::cerr << "dewpoint-simulate: " << e.what() << " (frames written so far are intact)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "dewpoint-simulate: " << e.what() << "\n";
    return 2;
  }
}
