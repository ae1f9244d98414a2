#include "path_tracer.h"

#include <algorithm>

#include "beer_lambert.h"
#include "shading_frame.h"

namespace dp::render {

namespace {

// Russian roulette starts once short paths, which carry most of the image,
// are complete; it then ends dim paths early without bias.
constexpr int kRouletteStartDepth = 3;
constexpr float kMaxSurvivalProbability = 0.95f;

// The interpolated normal bends the surface; where it would put wo on the
// other side than the true facet does, reflection and refraction would swap
// sides, so the facet's normal is used instead.
Vec3 normal_for_shading(const SurfaceHit& hit, Vec3 wo) {
  const bool facet_side = dot(wo, hit.geometric_normal) > 0;
  const bool shading_side = dot(wo, hit.shading_normal) > 0;
  return facet_side == shading_side ? hit.shading_normal : hit.geometric_normal;
}

}  // namespace

Rgb PathTracer::radiance(Ray ray, RandomStream& random) const {
  Rgb radiance{};
  Rgb throughput = Rgb::gray(1);
  // Absorption of the medium the path is travelling through. The camera is
  // in air; media do not nest (a path leaving any dielectric is in air again).
  Rgb medium_absorption{};
  for (int depth = 0; depth < max_depth_; ++depth) {
    const std::optional<SurfaceHit> hit = scene_.intersect(ray);
    if (!hit) {
      // A path can escape from inside a medium only through a hole in an
      // open mesh; the sky is then seen unattenuated rather than black.
      radiance += throughput * sky_.radiance(ray.direction);
      break;
    }
    if (!is_black(medium_absorption)) throughput *= beer_lambert_transmittance(medium_absorption, hit->distance);

    const Vec3 wo_world = -ray.direction;
    const ShadingFrame frame = ShadingFrame::around(normal_for_shading(*hit, wo_world));
    const Vec3 wo = frame.to_local(wo_world);
    const float u_lobe = random.uniform();
    const Sample2 u{random.uniform(), random.uniform()};
    const std::optional<BsdfSample> bsdf = hit->material->sample(wo, u_lobe, u);
    if (!bsdf) break;
    throughput *= bsdf->weight;
    if (is_black(throughput)) break;
    if (bsdf->wi.z * wo.z < 0) medium_absorption = bsdf->wi.z < 0 ? hit->material->absorption_per_m() : Rgb{};

    if (depth + 1 >= kRouletteStartDepth) {
      const float survival = std::min(kMaxSurvivalProbability, max_component(throughput));
      if (random.uniform() >= survival) break;
      throughput *= 1 / survival;
    }
    // The shading normal agrees with the facet on wo's side, so wi's side of
    // the shading frame is the side of the facet the path continues on.
    const Vec3 departure_side = bsdf->wi.z > 0 ? hit->geometric_normal : -hit->geometric_normal;
    ray = ray_leaving_surface(hit->position, departure_side, frame.to_world(bsdf->wi));
  }
  return radiance;
}

}  // namespace dp::render
