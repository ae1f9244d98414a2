#include "render_image.h"

#include <tbb/blocked_range2d.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <optional>

#include "path_tracer.h"
#include "pinhole_camera.h"
#include "random_stream.h"
#include "sky_environment.h"

namespace dp::render {

namespace {

constexpr int kTileSize = 16;

// A box filter: samples uniformly jittered over the pixel's square, averaged
// in double precision so thousands of samples lose nothing to rounding.
Rgb pixel_value(const PathTracer& tracer, const PinholeCamera& camera, const dp::io::RenderSettings& s, int x, int y) {
  double sum[3] = {0, 0, 0};
  for (int i = 0; i < s.spp; ++i) {
    RandomStream random(s.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), static_cast<std::uint32_t>(i));
    const float jitter_x = random.uniform(), jitter_y = random.uniform();
    const Rgb l = tracer.radiance(camera.ray_through(static_cast<float>(x) + jitter_x, static_cast<float>(y) + jitter_y), random);
    for (int c = 0; c < 3; ++c) sum[c] += l[c];
  }
  const double scale = 1.0 / s.spp;
  return {static_cast<float>(sum[0] * scale), static_cast<float>(sum[1] * scale), static_cast<float>(sum[2] * scale)};
}

}  // namespace

Image render_image(const RenderScene& scene, const dp::io::RenderSettings& settings, int threads) {
  std::optional<tbb::global_control> thread_limit;
  if (threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  const PinholeCamera camera(settings.camera, settings.width, settings.height);
  const SkyEnvironment sky(settings.environment);
  const PathTracer tracer(scene, sky, settings.max_depth);
  Image image(settings.width, settings.height);
  tbb::parallel_for(tbb::blocked_range2d<int>(0, settings.height, kTileSize, 0, settings.width, kTileSize),
                    [&](const tbb::blocked_range2d<int>& tile) {
                      for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
                        for (int x = tile.cols().begin(); x < tile.cols().end(); ++x)
                          image.at(x, y) = pixel_value(tracer, camera, settings, x, y);
                    });
  return image;
}

}  // namespace dp::render
