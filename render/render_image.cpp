#include "render_image.h"

#include <tbb/blocked_range2d.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <limits>
#include <optional>

#include "path_tracer.h"
#include "perspective_camera.h"
#include "random_stream.h"
#include "reconstruction_filter.h"

namespace dp::render {

namespace {

constexpr int kTileSize = 16;

struct PixelSums {
  double beauty[3] = {0, 0, 0}, albedo[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
  double depth = 0;
  int hits = 0;
};

struct Pixel {
  const PathTracer& tracer;
  const PerspectiveCamera& camera;
  const ReconstructionFilter& filter;
  const dp::io::RenderSettings& settings;

  // Sums in double precision, so thousands of samples lose nothing to rounding.
  void render(RenderedImage& image, int x, int y) const {
    PixelSums sums;
    for (int i = 0; i < settings.spp; ++i) {
      RandomStream random(settings.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), static_cast<std::uint32_t>(i),
                          settings.sampler == dp::io::SamplerType::Sobol ? SampleSequence::Sobol : SampleSequence::Independent);
      const Sample2 offset = filter.sample_offset(random.uniform2());
      const Sample2 lens = random.uniform2();
      const Ray ray = camera.ray_through(static_cast<float>(x) + 0.5f + offset.u1, static_cast<float>(y) + 0.5f + offset.u2, lens);
      const PathSample s = tracer.trace(ray, random);
      for (int c = 0; c < 3; ++c) {
        sums.beauty[c] += s.radiance[c];
        sums.albedo[c] += s.first.albedo[c];
        sums.normal[c] += s.first.normal[c];
      }
      if (s.first.hit) {
        sums.depth += s.first.distance * dot(ray.direction, camera.forward());
        ++sums.hits;
      }
    }
    const double scale = 1.0 / settings.spp;
    const auto mean = [&](const double* v) {
      return Rgb{static_cast<float>(v[0] * scale), static_cast<float>(v[1] * scale), static_cast<float>(v[2] * scale)};
    };
    image.beauty.at(x, y) = mean(sums.beauty);
    image.albedo.at(x, y) = mean(sums.albedo);
    image.normal.at(x, y) = mean(sums.normal);
    // Depth is not blended with the background: the nearest surface's mean
    // where any sample met one.
    image.depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(settings.width) + static_cast<std::size_t>(x)] =
        sums.hits > 0 ? static_cast<float>(sums.depth / sums.hits) : std::numeric_limits<float>::infinity();
  }
};

}  // namespace

RenderedImage render_image(const RenderScene& scene, const EnvironmentLight& environment,
                           const dp::io::RenderSettings& settings, int threads, const ProgressCallback& progress) {
  std::optional<tbb::global_control> thread_limit;
  if (threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  const PerspectiveCamera camera(settings.camera, settings.width, settings.height);
  const ReconstructionFilter filter(settings.filter);
  const PathTracer tracer(scene, environment, settings.max_depth);
  const Pixel pixel{tracer, camera, filter, settings};
  RenderedImage image(settings.width, settings.height);
  // A count of finished pixels only feeds the progress report; it never
  // touches the image, whose pixels depend on their own streams alone.
  std::atomic<long> pixels_done{0};
  const double total = static_cast<double>(settings.width) * settings.height;
  tbb::parallel_for(tbb::blocked_range2d<int>(0, settings.height, kTileSize, 0, settings.width, kTileSize),
                    [&](const tbb::blocked_range2d<int>& tile) {
                      for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
                        for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) pixel.render(image, x, y);
                      const long done = pixels_done += static_cast<long>(tile.rows().size() * tile.cols().size());
                      if (progress) progress(static_cast<double>(done) / total);
                    });
  return image;
}

RenderedImage render_image(const RenderScene& scene, const dp::io::RenderSettings& settings, int threads) {
  const std::unique_ptr<EnvironmentLight> environment = make_environment(settings.environment);
  return render_image(scene, *environment, settings, threads);
}

}  // namespace dp::render
