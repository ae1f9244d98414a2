#pragma once
// Renders one image of a scene: tiles in parallel, every pixel the box-
// filtered mean of its samples.
#include "image.h"
#include "render_scene.h"
#include "scene.h"

namespace dp::render {

// Uses settings' resolution, spp, max_depth, seed, camera and environment.
// threads: 0 lets TBB use every core. The result is the same, bit for bit,
// for every thread count.
Image render_image(const RenderScene& scene, const dp::io::RenderSettings& settings, int threads);

}  // namespace dp::render
