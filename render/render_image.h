#pragma once
// Renders one image of a scene: tiles in parallel (TBB), every pixel the
// mean of its filter-importance-sampled camera samples, with the auxiliary
// channels a compositor or denoiser wants.
#include <functional>

#include "environment_light.h"
#include "image.h"
#include "render_scene.h"
#include "render_settings.h"

namespace dp::render {

struct RenderedImage {
  Image beauty;
  Image albedo;              // first surface's reflectance (the environment's radiance where none)
  Image normal;              // first surface's world-space normal as (x, y, z); 0 where none
  std::vector<float> depth;  // distance along the camera axis to the first surface; +inf where none

  RenderedImage(int w, int h)
      : beauty(w, h), albedo(w, h), normal(w, h), depth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}
};

// Called from worker threads after each tile, with the fraction of pixels done.
using ProgressCallback = std::function<void(double fraction_done)>;

// Uses settings' resolution, spp, max_depth, seed, camera and filter.
// threads: 0 lets TBB use every core. The result is the same, bit for bit,
// for every thread count.
RenderedImage render_image(const RenderScene& scene, const EnvironmentLight& environment,
                           const dp::io::RenderSettings& settings, int threads, const ProgressCallback& progress = {});

// The same, with the environment settings' light.
RenderedImage render_image(const RenderScene& scene, const dp::io::RenderSettings& settings, int threads);

}  // namespace dp::render
