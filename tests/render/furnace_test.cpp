// White furnace: inside a uniform environment of radiance 1, an object that
// neither absorbs nor emits is invisible; every pixel's expected value is 1.
// Any energy the integrator or a material loses or invents shows up as a
// mean other than 1. The environment is both hit by BSDF sampling and
// sampled as a light, so the MIS weights of the two must sum to one.
//
// A rough dielectric of single-scattering microfacet theory (Walter 2007)
// does lose energy: light that would scatter between microfacets more than
// once is dropped (Heitz, Hanika, d'Eon & Dachsbacher 2016, "Multiple-
// Scattering Microfacet BSDFs with the Smith Model", Fig. 1). The loss at
// alpha 0.3 and 0.7 is measured and reported here.
#include <gtest/gtest.h>

#include "perspective_camera.h"
#include "render_image.h"
#include "render_scene.h"
#include "test_meshes.h"

namespace dp::render {
namespace {

// A unit sphere at the origin filling the whole frame: from 3 m away it
// subtends 19.5 degrees around the axis, the image's corners 16.4 degrees.
dp::io::RenderSettings furnace_settings() {
  dp::io::RenderSettings s;
  s.width = 40;
  s.height = 30;
  s.spp = 64;
  s.max_depth = 64;  // paths are cut off only where their energy is negligible
  s.camera.position_m = {0, 0, 3};
  s.camera.look_at_m = {0, 0, 0};
  s.camera.fov_deg = 20;
  s.environment.type = dp::io::EnvironmentType::Constant;
  s.environment.radiance = {1, 1, 1};
  s.environment.intensity = 1;
  return s;
}

Rgb mean(const Image& image) {
  double sum[3] = {0, 0, 0};
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) sum[c] += p[c];
  const double n = static_cast<double>(image.pixels.size());
  return {static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n), static_cast<float>(sum[2] / n)};
}

Rgb furnace_mean(const dp::io::Material& material) {
  const RenderScene scene({{"sphere", test::icosphere({0, 0, 0}, 1, 4), material, ShadingNormals::Interpolated}});
  const dp::io::RenderSettings settings = furnace_settings();
  // Every corner ray must meet the sphere, or the test would see the sky.
  const PerspectiveCamera camera(settings.camera, settings.width, settings.height);
  for (int x : {0, settings.width})
    for (int y : {0, settings.height})
      EXPECT_TRUE(scene.intersect(camera.ray_through(static_cast<float>(x), static_cast<float>(y))));
  const Rgb m = mean(render_image(scene, settings, 0).beauty);
  std::printf("furnace mean: %.6f %.6f %.6f\n", m.r, m.g, m.b);
  return m;
}

TEST(render_furnace, WhiteLambertianSphereVanishes) {
  dp::io::Material white;
  white.type = dp::io::MaterialType::Diffuse;
  white.albedo = {1, 1, 1};
  const Rgb m = furnace_mean(white);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], 1.0f, 0.01f) << "channel " << c;
}

TEST(render_furnace, ClearDielectricSphereVanishes) {
  dp::io::Material water;
  water.type = dp::io::MaterialType::Dielectric;
  water.ior = 1.33;
  water.absorption_per_m = {0, 0, 0};
  const Rgb m = furnace_mean(water);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], 1.0f, 0.01f) << "channel " << c;
}

TEST(render_furnace, RoughDielectricSphereLosesOnlyMultipleScattering) {
  dp::io::Material glass;
  glass.type = dp::io::MaterialType::Dielectric;
  glass.ior = 1.33;
  double loss[2];
  int i = 0;
  for (double alpha : {0.3, 0.7}) {
    glass.roughness = glass.fogged_roughness = glass.wet_roughness = alpha;
    const Rgb m = furnace_mean(glass);
    loss[i] = 1 - m.g;
    std::printf("rough dielectric, IOR 1.33, alpha %.1f: furnace mean %.4f, energy loss %.2f %%\n", alpha, m.g, 100 * loss[i]);
    ++i;
  }
  // Single scattering can only lose energy, and loses more the rougher the
  // surface (Heitz et al. 2016, Fig. 1).
  EXPECT_GT(loss[0], 0.0);
  EXPECT_GT(loss[1], loss[0]);
}

TEST(render_furnace, NearlySmoothDielectricIsTheSmoothOne) {
  dp::io::Material glass;
  glass.type = dp::io::MaterialType::Dielectric;
  glass.roughness = glass.fogged_roughness = glass.wet_roughness = 1e-4;
  const Rgb m = furnace_mean(glass);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], 1.0f, 0.01f) << "channel " << c;
}

}  // namespace
}  // namespace dp::render
