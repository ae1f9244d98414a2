// dewpoint-render: renders every frame's liquid surface with the scene's
// rigids under its sky, writing beauty.NNNN.{exr,png,json}.
#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <tuple>

#include "cli_common.h"
#include "dewpoint/version.h"
#include "frame_sidecar.h"
#include "frames.h"
#include "image_output.h"
#include "liquid_mesh.h"
#include "pinhole_camera.h"
#include "render_image.h"
#include "render_scene.h"
#include "scene.h"
#include "scene_objects.h"

namespace fs = std::filesystem;

namespace {

struct Options {
  fs::path scene;
  fs::path frames_dir;
  fs::path meshes_dir;
  fs::path out;
  std::string frames;
  std::optional<int> spp;
  std::string resolution;
  std::optional<std::int64_t> seed;
  int threads = 0;
  bool quiet = false;
};

struct FrameJob {
  dp::io::FrameEntry entry;
  fs::path liquid_mesh;
};

// "WxH", both positive.
std::pair<int, int> parse_resolution(const std::string& text) {
  const auto fail = [&] { return std::invalid_argument("--resolution: expected WxH with positive integers, found '" + text + "'"); };
  const auto x = text.find('x');
  if (x == std::string::npos) throw fail();
  const std::string w = text.substr(0, x), h = text.substr(x + 1);
  for (const std::string& part : {w, h})
    if (part.empty() || part.size() > 6 || part.find_first_not_of("0123456789") != std::string::npos) throw fail();
  const int width = std::stoi(w), height = std::stoi(h);
  if (width <= 0 || height <= 0) throw fail();
  return {width, height};
}

dp::io::RenderSettings settings_with_overrides(const dp::io::Scene& scene, const Options& opt) {
  dp::io::RenderSettings s = scene.render;
  if (opt.spp) s.spp = *opt.spp;
  if (opt.seed) s.seed = static_cast<std::uint64_t>(*opt.seed);
  if (!opt.resolution.empty()) std::tie(s.width, s.height) = parse_resolution(opt.resolution);
  try {
    const dp::render::PinholeCamera camera_check(s.camera, s.width, s.height);  // throws on a degenerate view
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(scene.file.string() + ": " + e.what());
  }
  return s;
}

// The manifest's frames in the requested range, each with its liquid mesh,
// which must exist before anything is rendered.
std::vector<FrameJob> frame_jobs(const Options& opt) {
  const dp::io::FramesManifest manifest = dp::io::read_manifest(opt.frames_dir);
  const dp::io::FrameRange range = opt.frames.empty() ? dp::io::FrameRange{} : dp::io::parse_frame_range(opt.frames);
  std::vector<FrameJob> jobs;
  for (const dp::io::FrameEntry& entry : manifest.frames) {
    if (!range.contains(entry.index)) continue;
    fs::path mesh = opt.meshes_dir / dp::io::frame_file_name("liquid", entry.index, "ply");
    if (!fs::exists(mesh))
      throw std::runtime_error(mesh.string() + ": liquid mesh of frame " + std::to_string(entry.index) +
                               " not found (has dewpoint-mesh run for it?)");
    jobs.push_back({entry, mesh});
  }
  if (jobs.empty())
    throw std::invalid_argument("--frames: no frame of " + (opt.frames_dir / "manifest.json").string() + " in range '" + opt.frames + "'");
  return jobs;
}

int run(const Options& opt) {
  // Everything that can be wrong with the input is found before any output
  // exists: scene, overrides, manifest, meshes.
  const dp::io::Scene scene = dp::io::load_scene(opt.scene);
  const dp::io::RenderSettings settings = settings_with_overrides(scene, opt);
  const std::vector<FrameJob> jobs = frame_jobs(opt);
  const std::vector<dp::render::SceneObject> rigids = dp::render::load_rigid_objects(scene);

  // Limits Embree's BVH builds as well as the rendering.
  std::optional<tbb::global_control> thread_limit;
  if (opt.threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(opt.threads));

  fs::create_directories(opt.out);
  const std::string software = std::string("dewpoint-render ") + dp::kVersion;
  dp::io::Progress progress("render " + scene.name, static_cast<long>(jobs.size()), opt.quiet);
  long done = 0;
  for (const FrameJob& job : jobs) {
    std::vector<dp::render::SceneObject> objects = rigids;
    objects.push_back(dp::render::liquid_object(dp::render::load_liquid_mesh(job.liquid_mesh), settings));
    const dp::render::RenderScene render_scene(objects);

    const auto start = std::chrono::steady_clock::now();
    const dp::render::Image image = dp::render::render_image(render_scene, settings, opt.threads);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const int f = job.entry.index;
    dp::render::write_exr(opt.out / dp::io::frame_file_name("beauty", f, "exr"), image, software);
    dp::render::write_png_preview(opt.out / dp::io::frame_file_name("beauty", f, "png"), image, settings.exposure_stops, software);
    const dp::render::FrameRecord record{.scene_file = scene.file,
                                         .liquid_mesh = job.liquid_mesh,
                                         .frame = f,
                                         .frame_time_s = job.entry.time_s,
                                         .width = settings.width,
                                         .height = settings.height,
                                         .spp = settings.spp,
                                         .max_depth = settings.max_depth,
                                         .seed = settings.seed,
                                         .exposure_stops = settings.exposure_stops,
                                         .threads = opt.threads,
                                         .render_time_s = seconds};
    dp::render::write_sidecar(opt.out / dp::io::frame_file_name("beauty", f, "json"), record);
    char detail[64];
    std::snprintf(detail, sizeof detail, "frame %d in %.2f s", f, seconds);
    progress.update(++done, detail);
  }
  progress.finish(std::to_string(jobs.size()) + " frames in " + opt.out.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dewpoint-render: path-traces each frame's liquid mesh with the scene's rigids and sky"};
  app.set_version_flag("--version", std::string("dewpoint-render ") + dp::kVersion);
  Options opt;
  app.add_option("scene", opt.scene, "scene file (JSON)")->required();
  app.add_option("--frames-dir", opt.frames_dir, "frames folder of dewpoint-simulate (holds manifest.json)")->required();
  app.add_option("--meshes-dir", opt.meshes_dir, "folder of dewpoint-mesh's liquid.NNNN.ply")->required();
  app.add_option("-o,--output", opt.out, "output folder for beauty.NNNN.{exr,png,json}")->required();
  app.add_option("--frames", opt.frames, "frames to render, A-B (inclusive), A- or A");
  app.add_option("--spp", opt.spp, "samples per pixel (default: the scene's render.spp)")->check(CLI::Range(1, 1 << 20));
  app.add_option("--resolution", opt.resolution, "image size WxH (default: the scene's render.resolution)");
  app.add_option("--seed", opt.seed, "random seed (default: the scene's render.seed)")
      ->check(CLI::Range(std::int64_t{0}, std::numeric_limits<std::int64_t>::max()));
  app.add_option("--threads", opt.threads, "CPU threads (0: all); images are identical for any count")
      ->check(CLI::Range(0, 1 << 16));
  app.add_flag("--quiet", opt.quiet, "no progress output");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "dewpoint-render: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    return run(opt);
  } catch (const std::exception& e) {
    std::cerr << "dewpoint-render: " << e.what() << "\n";
    return 2;
  }
}
