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
#include "frame_progress.h"
#include "frame_sidecar.h"
#include "frames.h"
#include "image_output.h"
#include "liquid_mesh.h"
#include "log_options.h"
#include "perspective_camera.h"
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
  std::string aovs;
  bool no_wet_paths = false;
  bool quiet = false;
  std::optional<std::string> preset;
};

const char* camera_name(dp::io::CameraModel m) { return m == dp::io::CameraModel::ThinLens ? "thin_lens" : "pinhole"; }
const char* filter_name(dp::io::FilterType f) {
  return f == dp::io::FilterType::Box ? "box" : (f == dp::io::FilterType::Tent ? "tent" : "gaussian");
}
const char* environment_name(dp::io::EnvironmentType e) {
  return e == dp::io::EnvironmentType::Map ? "map" : (e == dp::io::EnvironmentType::Constant ? "constant" : "sky");
}
std::string aov_names(const dp::io::AovSelection& a) {
  std::string names;
  for (auto [on, name] : {std::pair{a.albedo, "albedo"}, {a.normal, "normal"}, {a.depth, "depth"}})
    if (on) names += (names.empty() ? "" : ",") + std::string(name);
  return names.empty() ? "none" : names;
}

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
  if (!opt.aovs.empty()) {
    try {
      s.aovs = dp::io::parse_aov_list(opt.aovs);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--aov: ") + e.what());
    }
  }
  if (opt.no_wet_paths) s.wet_paths = false;
  try {
    const dp::render::PerspectiveCamera camera_check(s.camera, s.width, s.height);  // throws on a degenerate view
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
  // exists: scene, overrides, manifest, meshes, environment map.
  const std::string preset = opt.preset.value_or(dp::io::recorded_preset(dp::io::read_manifest(opt.frames_dir)));
  const dp::io::Scene scene = dp::io::load_scene(opt.scene, preset);
  const dp::io::RenderSettings settings = settings_with_overrides(scene, opt);
  const std::vector<FrameJob> jobs = frame_jobs(opt);
  const std::vector<dp::render::SceneObject> rigids = dp::render::load_rigid_objects(scene, opt.frames_dir);
  const std::unique_ptr<dp::render::EnvironmentLight> environment = dp::render::make_environment(settings.environment);

  // Limits Embree's BVH builds as well as the rendering.
  std::optional<tbb::global_control> thread_limit;
  if (opt.threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(opt.threads));

  fs::create_directories(opt.out);
  const std::string software = std::string("dewpoint-render ") + dp::kVersion;
  dp::render::FrameProgress progress("render " + scene.name, jobs.size(), opt.quiet);
  std::size_t done = 0;
  for (const FrameJob& job : jobs) {
    const int f = job.entry.index;
    std::vector<dp::render::SceneObject> objects = rigids;
    const std::vector<fs::path> textures = dp::render::attach_surface_textures(objects, opt.frames_dir, f);
    objects.push_back(dp::render::liquid_object(dp::render::load_liquid_mesh(job.liquid_mesh), settings));
    const dp::render::RenderScene render_scene(objects, settings.wet_paths);

    const auto start = std::chrono::steady_clock::now();
    const dp::render::RenderedImage image = dp::render::render_image(
        render_scene, *environment, settings, opt.threads, [&](double fraction) { progress.tile_done(done, f, fraction); });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    dp::render::write_exr(opt.out / dp::io::frame_file_name("beauty", f, "exr"), image, settings.aovs, software);
    dp::render::write_png_preview(opt.out / dp::io::frame_file_name("beauty", f, "png"), image.beauty, settings.exposure_stops, software);
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
                                         .render_time_s = seconds,
                                         .sampler = settings.sampler == dp::io::SamplerType::Sobol ? "sobol" : "independent",
                                         .camera = camera_name(settings.camera.model),
                                         .filter = filter_name(settings.filter.type),
                                         .environment = environment_name(settings.environment.type),
                                         .aovs = aov_names(settings.aovs),
                                         .wet_paths = settings.wet_paths,
                                         .area_light_triangles = render_scene.area_lights().count(),
                                         .surface_textures = textures};
    dp::render::write_sidecar(opt.out / dp::io::frame_file_name("beauty", f, "json"), record);
    char detail[96];
    const double samples = static_cast<double>(settings.width) * settings.height * settings.spp;
    std::snprintf(detail, sizeof detail, "frame %d in %.2f s, %.2f M samples/s", f, seconds, samples / seconds * 1e-6);
    progress.frame_done(++done, detail);
  }
  progress.finish(std::to_string(jobs.size()) + " frames in " + opt.out.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dewpoint-render: path-traces each frame's liquid mesh with the scene's rigids, lights and environment"};
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
  app.add_option("--aov", opt.aovs, "auxiliary EXR channels: comma-separated albedo,normal,depth, or none (default: the scene's render.aovs)");
  app.add_option("--preset", opt.preset, "scene preset (default: the one the frames were simulated with)");
  app.add_flag("--no-wet-paths", opt.no_wet_paths, "ignore the surface textures' wetting history");
  dp::io::LogOptions log;  // progress is info; these tools have no debug lines
  dp::io::add_log_options(app, log);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "dewpoint-render: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    opt.quiet = !dp::io::logs(log.effective(), dp::io::LogLevel::Info);
    return run(opt);
  } catch (const std::exception& e) {
    std::cerr << "dewpoint-render: " << e.what() << "\n";
    return 2;
  }
}
