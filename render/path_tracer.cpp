#include "path_tracer.h"

#include <algorithm>
#include <cmath>

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

Vec3 side_of(const SurfaceHit& hit, Vec3 direction) {
  return dot(direction, hit.geometric_normal) > 0 ? hit.geometric_normal : -hit.geometric_normal;
}

// Light leaves an emitter from its front (outside) only.
Rgb emitted_towards(const SurfaceHit& hit, Vec3 towards) {
  if (!hit.material->emissive() || dot(towards, hit.geometric_normal) <= 0) return {};
  return hit.material->emission();
}

}  // namespace

PathTracer::PathTracer(const RenderScene& scene, const EnvironmentLight& environment, int max_depth)
    : scene_(scene), environment_(environment), max_depth_(max_depth) {
  const bool area = !scene.area_lights().empty(), env = !environment.black();
  environment_probability_ = env ? (area ? 0.5f : 1.0f) : 0.0f;
}

float PathTracer::environment_light_pdf(Vec3 direction) const {
  return environment_probability_ > 0 ? environment_probability_ * environment_.pdf(direction) : 0.0f;
}

float PathTracer::area_light_pdf(const SurfaceHit& light_hit, Vec3 from) const {
  const float area_probability = 1 - environment_probability_;
  if (!(area_probability > 0)) return 0;
  const Vec3 d = light_hit.position - from;
  const float cos_light = std::abs(dot(light_hit.geometric_normal, normalize(d)));
  if (!(cos_light > 0)) return 0;
  // Area density to solid angle: dω = cos / r² dA.
  return area_probability * scene_.area_lights().pdf_area(light_hit.geometry, light_hit.primitive) * length_squared(d) /
         cos_light;
}

Rgb PathTracer::sample_direct_light(const SurfaceHit& hit, const Bsdf& bsdf, const ShadingFrame& frame, Vec3 wo,
                                    Rgb medium_absorption, float u_choice, Sample2 u) const {
  Vec3 wi_world;
  Rgb incoming;
  float light_pdf = 0;
  if (u_choice < environment_probability_) {
    const EnvironmentSample s = environment_.sample(u);
    if (!(s.pdf > 0) || is_black(s.radiance)) return {};
    wi_world = s.direction;
    incoming = s.radiance;
    light_pdf = environment_probability_ * s.pdf;
    if (!scene_.escapes(ray_leaving_surface(hit.position, side_of(hit, wi_world), wi_world))) return {};
  } else {
    if (scene_.area_lights().empty()) return {};
    const float u_pick = (u_choice - environment_probability_) / (1 - environment_probability_);
    const AreaLightSample s = scene_.area_lights().sample(std::min(u_pick, 0.99999994f), u);
    const Vec3 d = s.position - hit.position;
    const float distance2 = length_squared(d);
    if (!(distance2 > 0) || !(s.pdf_area > 0)) return {};
    wi_world = (1 / std::sqrt(distance2)) * d;
    const float cos_light = -dot(s.normal, wi_world);
    if (cos_light <= 0) return {};  // the light's back
    light_pdf = (1 - environment_probability_) * s.pdf_area * distance2 / cos_light;
    const Ray shadow = ray_leaving_surface(hit.position, side_of(hit, wi_world), wi_world);
    if (!scene_.visible(shadow.origin, s.position)) return {};
    incoming = s.radiance;
    if (!is_black(medium_absorption)) incoming *= beer_lambert_transmittance(medium_absorption, std::sqrt(distance2));
  }
  const Vec3 wi = frame.to_local(wi_world);
  const Rgb f = bsdf.eval(wo, wi);
  if (is_black(f)) return {};
  const float weight = power_heuristic(light_pdf, bsdf.pdf(wo, wi));
  return f * incoming * (std::abs(wi.z) * weight / light_pdf);
}

PathSample PathTracer::trace(Ray ray, RandomStream& random) const {
  PathSample result;
  Rgb throughput = Rgb::gray(1);
  // Absorption of the medium the path is travelling through. The camera is
  // in air; media do not nest (a path leaving any dielectric is in air again).
  Rgb medium_absorption{};
  // How the last direction was chosen, for weighting light it finds.
  bool last_specular = true;
  float last_pdf = 0;
  Vec3 last_position = ray.origin;
  for (int depth = 0; depth < max_depth_; ++depth) {
    const std::optional<SurfaceHit> hit = scene_.intersect(ray);
    if (!hit) {
      // A path can escape from inside a medium only through a hole in an
      // open mesh; the sky is then seen unattenuated rather than black.
      const Rgb sky = environment_.radiance(ray.direction);
      const float weight = last_specular ? 1.0f : power_heuristic(last_pdf, environment_light_pdf(ray.direction));
      result.radiance += throughput * sky * weight;
      if (depth == 0) result.first.albedo = sky;
      break;
    }
    if (!is_black(medium_absorption)) throughput *= beer_lambert_transmittance(medium_absorption, hit->distance);

    const Vec3 wo_world = -ray.direction;
    const Rgb emitted = emitted_towards(*hit, wo_world);
    if (!is_black(emitted)) {
      const float weight = last_specular ? 1.0f : power_heuristic(last_pdf, area_light_pdf(*hit, last_position));
      result.radiance += throughput * emitted * weight;
    }

    const ShadingFrame frame = ShadingFrame::around(normal_for_shading(*hit, wo_world));
    const Vec3 wo = frame.to_local(wo_world);
    const Bsdf bsdf = hit->material->bsdf_at(hit->surface);
    if (depth == 0) result.first = {true, hit->distance, hit->shading_normal, bsdf.albedo()};

    // Every vertex draws the same numbers in the same order, used or not,
    // so a dimension of a stratified sequence always serves one purpose.
    const float u_light_choice = random.uniform();
    const Sample2 u_light = random.uniform2();
    const float u_lobe = random.uniform();
    const Sample2 u = random.uniform2();
    const float u_roulette = random.uniform();
    if (!bsdf.specular())
      result.radiance += throughput * sample_direct_light(*hit, bsdf, frame, wo, medium_absorption, u_light_choice, u_light);

    const std::optional<BsdfSample> scattered = bsdf.sample(wo, u_lobe, u);
    if (!scattered) break;
    throughput *= scattered->weight;
    if (is_black(throughput)) break;
    if (scattered->wi.z * wo.z < 0) medium_absorption = scattered->wi.z < 0 ? hit->material->absorption_per_m() : Rgb{};
    last_specular = scattered->specular;
    last_pdf = scattered->pdf;
    last_position = hit->position;

    if (depth + 1 >= kRouletteStartDepth) {
      const float survival = std::min(kMaxSurvivalProbability, max_component(throughput));
      if (u_roulette >= survival) break;
      throughput *= 1 / survival;
    }
    // The shading normal agrees with the facet on wo's side, so wi's side of
    // the shading frame is the side of the facet the path continues on.
    const Vec3 departure_side = scattered->wi.z > 0 ? hit->geometric_normal : -hit->geometric_normal;
    ray = ray_leaving_surface(hit->position, departure_side, frame.to_world(scattered->wi));
  }
  return result;
}

}  // namespace dp::render
