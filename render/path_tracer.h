#pragma once
// Unidirectional path tracing (Kajiya 1986) with next-event estimation:
// at every non-specular vertex one light sample (environment or emissive
// triangle) is connected by a shadow ray, and light found by the BSDF-
// sampled continuation is counted too; the two estimates are combined by
// multiple importance sampling with the power heuristic (Veach & Guibas
// 1995, beta = 2). Specular vertices (smooth water, glass, mirrors) are
// passed through by sampling alone, with Fresnel-weighted reflection,
// refraction and total internal reflection, and light reached after them
// counts fully. Russian roulette ends dim paths without bias.
#include "environment_light.h"
#include "random_stream.h"
#include "render_scene.h"
#include "rgb.h"
#include "shading_frame.h"

namespace dp::render {

// What the camera ray meets first, for the auxiliary image channels.
struct FirstHit {
  bool hit = false;
  float distance = 0;  // along the camera ray
  Vec3 normal;         // world-space shading normal, towards the outside
  Rgb albedo;          // the BSDF's reflectance; the environment's radiance where nothing is hit
};

struct PathSample {
  Rgb radiance;
  FirstHit first;
};

class PathTracer {
 public:
  // max_depth: the most surface interactions a path may have; longer paths
  // are cut off (their remaining contribution is lost).
  PathTracer(const RenderScene& scene, const EnvironmentLight& environment, int max_depth);

  // Radiance arriving at ray.origin from along -ray.direction, one sample.
  PathSample trace(Ray ray, RandomStream& random) const;
  Rgb radiance(Ray ray, RandomStream& random) const { return trace(ray, random).radiance; }

 private:
  // One light sample at a scattering vertex, MIS-weighted against the BSDF.
  Rgb sample_direct_light(const SurfaceHit& hit, const Bsdf& bsdf, const ShadingFrame& frame, Vec3 wo,
                          Rgb medium_absorption, float u_choice, Sample2 u) const;
  // Density with which light sampling would have chosen this direction.
  float environment_light_pdf(Vec3 direction) const;
  float area_light_pdf(const SurfaceHit& light_hit, Vec3 from) const;

  const RenderScene& scene_;
  const EnvironmentLight& environment_;
  int max_depth_;
  float environment_probability_;  // of choosing the environment over the area lights
};

// Veach's power heuristic with beta = 2, weighting the strategy with density a.
inline float power_heuristic(float a, float b) {
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0f;
}

}  // namespace dp::render
