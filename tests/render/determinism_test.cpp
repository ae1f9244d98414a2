// Every pixel draws from its own counter-based random streams, so the image
// must not depend on how tiles are spread over threads, and must depend on
// the seed.
#include <gtest/gtest.h>

#include <cstring>

#include "image_environment.h"
#include "render_image.h"
#include "render_scene.h"
#include "test_meshes.h"

namespace dp::render {
namespace {

class render_determinism : public ::testing::Test {
 protected:
  render_determinism()
      : scene_({{"floor", test::box({-1, -0.1f, -1}, {1, 0, 1}), diffuse(), ShadingNormals::Geometric},
                {"drop", test::icosphere({0, 0.2f, 0}, 0.2f, 3), water(), ShadingNormals::Interpolated}}) {
    settings_.width = 48;  // three tiles across, two down
    settings_.height = 20;
    settings_.spp = 4;
    settings_.camera.position_m = {0.6, 0.5, 0.9};
    settings_.camera.look_at_m = {0, 0.15, 0};
  }

  static dp::io::Material diffuse() {
    dp::io::Material m;
    m.albedo = {0.7, 0.6, 0.5};
    return m;
  }
  static dp::io::Material water() {
    dp::io::Material m;
    m.type = dp::io::MaterialType::Dielectric;
    m.absorption_per_m = {2, 0.6, 0.3};
    return m;
  }

  static bool bit_identical(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
  }

  RenderScene scene_;
  dp::io::RenderSettings settings_;
};

TEST_F(render_determinism, OneAndTwoThreadsGiveTheSameBits) {
  const Image one = render_image(scene_, settings_, 1).beauty;
  const Image two = render_image(scene_, settings_, 2).beauty;
  EXPECT_TRUE(bit_identical(one, two));
}

TEST_F(render_determinism, SameSeedSameImageOtherSeedOtherImage) {
  const Image first = render_image(scene_, settings_, 0).beauty;
  EXPECT_TRUE(bit_identical(first, render_image(scene_, settings_, 0).beauty));
  settings_.seed += 1;
  const Image reseeded = render_image(scene_, settings_, 0).beauty;
  ASSERT_EQ(first.pixels.size(), reseeded.pixels.size());
  int differing = 0;
  for (std::size_t i = 0; i < first.pixels.size(); ++i)
    differing += std::memcmp(&first.pixels[i], &reseeded.pixels[i], sizeof(Rgb)) != 0;
  // Sky pixels seen past everything are the same for any seed; most others differ.
  EXPECT_GT(differing, static_cast<int>(first.pixels.size() / 4));
}

TEST_F(render_determinism, EveryFeatureTogetherIsThreadCountInvariant) {
  // Rough glass, rough metal, an area light, an HDR map, a thin lens and a
  // Gaussian filter: next-event estimation, MIS and lens sampling all draw
  // from the per-sample streams.
  dp::io::Material glass = water(), metal, lamp;
  glass.roughness = glass.fogged_roughness = glass.wet_roughness = 0.3;
  metal.type = dp::io::MaterialType::Conductor;
  metal.roughness = metal.fogged_roughness = metal.wet_roughness = 0.2;
  lamp.albedo = {0, 0, 0};
  lamp.emission = {5, 5, 5};
  const RenderScene scene({{"floor", test::box({-1, -0.1f, -1}, {1, 0, 1}), diffuse(), ShadingNormals::Geometric},
                           {"drop", test::icosphere({0, 0.2f, 0}, 0.2f, 3), glass, ShadingNormals::Interpolated},
                           {"block", test::box({0.2f, 0, -0.4f}, {0.4f, 0.2f, -0.2f}), metal, ShadingNormals::Geometric},
                           {"lamp", test::disk_facing_down({0, 1, 0}, 0.2f, 16), lamp, ShadingNormals::Geometric}});
  std::vector<Rgb> sky(32 * 16, Rgb{0.3f, 0.4f, 0.6f});
  sky[3 * 32 + 5] = Rgb::gray(200);
  const ImageEnvironment environment(sky, 32, 16, 1, 0);
  settings_.camera.model = dp::io::CameraModel::ThinLens;
  settings_.camera.aperture_radius_m = 0.02;
  const RenderedImage one = render_image(scene, environment, settings_, 1);
  const RenderedImage two = render_image(scene, environment, settings_, 2);
  EXPECT_TRUE(bit_identical(one.beauty, two.beauty));
  EXPECT_TRUE(bit_identical(one.albedo, two.albedo));
  EXPECT_TRUE(bit_identical(one.normal, two.normal));
  EXPECT_EQ(std::memcmp(one.depth.data(), two.depth.data(), one.depth.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace dp::render
