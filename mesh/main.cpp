// dewpoint-mesh: turns a frames folder's liquid particles into one surface
// mesh per frame.
#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli_common.h"
#include "dewpoint/version.h"
#include "log_options.h"
#include "mesh_frames.h"

namespace {

struct Options {
  std::string frames_dir, out_dir, frames;
  double voxel_size = 0, voxels_per_radius = 0;
  int threads = 0;
  bool quiet = false, no_correction = false, check = false, level_set = false;
  double contact_angle_deg = 0;
  std::optional<std::string> preset;
};

int run(const Options& opt) {
  dp::mesh::MeshFramesOptions job;
  job.frames_dir = opt.frames_dir;
  job.out_dir = opt.out_dir;
  job.range = opt.frames.empty() ? dp::io::FrameRange{} : dp::io::parse_frame_range(opt.frames);
  job.voxel_size = opt.voxel_size;
  job.voxels_per_radius = opt.voxels_per_radius;
  job.quiet = opt.quiet;
  job.no_correction = opt.no_correction;
  job.contact_angle_deg = opt.contact_angle_deg;
  job.check = opt.check;
  job.level_set = opt.level_set;
  job.preset = opt.preset;
  // The limit lives as long as this object: for the whole run.
  std::unique_ptr<tbb::global_control> limit;
  if (opt.threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, opt.threads);
  job.threads = static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  const dp::mesh::MeshFramesResult result = dp::mesh::mesh_frames(job);
  if (result.failed_checks > 0) {
    std::cerr << "dewpoint-mesh: --check: " << result.failed_checks << " of " << result.frames
              << " meshes failed (see \"check\" in their sidecars)\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dewpoint-mesh: meshes the liquid surface of each frame of a dewpoint-simulate frames folder"};
  app.set_version_flag("--version", std::string("dewpoint-mesh ") + dp::kVersion);
  Options opt;
  app.add_option("frames", opt.frames_dir, "frames folder (with manifest.json) written by dewpoint-simulate")->required();
  app.add_option("-o,--output", opt.out_dir, "output folder for liquid.NNNN.ply and liquid.NNNN.json")->required();
  app.add_option("--frames", opt.frames, "frames to mesh, A-B (inclusive), A- or A");
  auto* voxel = app.add_option("--voxel-size", opt.voxel_size, "voxel size in metres")->check(CLI::PositiveNumber);
  app.add_option("--voxels-per-radius", opt.voxels_per_radius,
                 "voxels per particle radius (default: the scene's mesh.voxels_per_radius)")
      ->check(CLI::PositiveNumber)
      ->excludes(voxel);
  app.add_flag("--no-correction", opt.no_correction,
               "plain Zhu-Bridson surface (paper Eq. 19), without the wall corrections of Eq. 20-24");
  app.add_option("--contact-angle", opt.contact_angle_deg,
                 "static contact angle alpha_base in degrees for every rigid (default: the scene's mesh section)")
      ->check(CLI::Range(0.0, 180.0) & CLI::PositiveNumber);
  app.add_option("--preset", opt.preset, "scene preset (default: the one the frames were simulated with)");
  app.add_flag("--check", opt.check,
               "check every mesh with CGAL (closed, manifold, oriented, self-intersections, volume, area); exit code 1 "
               "if one fails");
  app.add_flag("--level-set", opt.level_set,
               "also write the field the mesh contours as an OpenVDB level set, liquid.NNNN.vdb (default: the scene's "
               "mesh.level_set)");
  app.add_option("--threads", opt.threads, "CPU threads (0: all)")->check(CLI::Range(0, 4096));
  dp::io::LogOptions log;  // progress is info; these tools have no debug lines
  dp::io::add_log_options(app, log);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end parsing too, successfully; a bad command
    // line is bad input like any other: one line, exit code 2
    // (docs/architecture.md).
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "dewpoint-mesh: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    opt.quiet = !dp::io::logs(log.effective(), dp::io::LogLevel::Info);
    return run(opt);
  } catch (const std::exception& e) {
    std::cerr << "dewpoint-mesh: " << e.what() << "\n";
    return 2;
  }
}
