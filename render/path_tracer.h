#pragma once
// Unidirectional path tracing with BSDF sampling only: a path gathers light
// when it escapes to the sky. That suffices for a smooth, low-frequency sky
// and smooth dielectrics (which no light sampling could reach anyway);
// small bright lights would need next-event estimation with multiple
// importance sampling, which Material's eval/pdf are there for.
#include "random_stream.h"
#include "render_scene.h"
#include "rgb.h"
#include "sky_environment.h"

namespace dp::render {

class PathTracer {
 public:
  // max_depth: the most surface interactions a path may have; longer paths
  // are cut off (their remaining contribution is lost).
  PathTracer(const RenderScene& scene, const SkyEnvironment& sky, int max_depth)
      : scene_(scene), sky_(sky), max_depth_(max_depth) {}

  // Radiance arriving at ray.origin from along -ray.direction, one sample.
  Rgb radiance(Ray ray, RandomStream& random) const;

 private:
  const RenderScene& scene_;
  const SkyEnvironment& sky_;
  int max_depth_;
};

}  // namespace dp::render
