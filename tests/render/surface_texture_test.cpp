// The simulator's surface texture as the renderer reads it: channel names
// and layout of the frame-folder contract (row 0 at the top, texel centres
// at u = (col + 0.5)/W, v = 1 - (row + 0.5)/H), bilinear between texel
// centres, and the roughness rule alpha = lerp(alpha_dry, alpha_fogged,
// clamp(m/m_max)) with wet paths on top.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "material.h"
#include "surface_texture.h"
#include "test_textures.h"

namespace fs = std::filesystem;

namespace dp::render {
namespace {

class render_surface_texture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("dewpoint_render_texture_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(render_surface_texture, TexelCentresFollowTheContractsOrientation) {
  // 2 x 2 texels: fog 0.1 top-left, 0.2 top-right, 0.3 bottom-left, 0.4 bottom-right.
  const fs::path file = dir_ / "surface_mirror.0003.exr";
  test::write_surface_exr(file, 2, 2, {0.1f, 0.2f, 0.3f, 0.4f}, {1, 1, 1, 1}, {0, 0, 1, 0});
  const SurfaceTexture t = SurfaceTexture::load(file);
  EXPECT_NEAR(t.at(0.25f, 0.75f).fog, 0.1f, 1e-6f);  // top-left centre: row 0, v high
  EXPECT_NEAR(t.at(0.75f, 0.75f).fog, 0.2f, 1e-6f);
  EXPECT_NEAR(t.at(0.25f, 0.25f).fog, 0.3f, 1e-6f);
  EXPECT_NEAR(t.at(0.75f, 0.25f).wetting, 0.0f, 1e-6f);
  EXPECT_NEAR(t.at(0.25f, 0.25f).wetting, 1.0f, 1e-6f);
  // Halfway between all four centres: their mean; a quarter of the way: the bilinear blend.
  EXPECT_NEAR(t.at(0.5f, 0.5f).fog, 0.25f, 1e-6f);
  EXPECT_NEAR(t.at(0.375f, 0.625f).fog, 0.75f * 0.75f * 0.1f + 0.25f * 0.75f * 0.2f + 0.75f * 0.25f * 0.3f + 0.25f * 0.25f * 0.4f, 1e-6f);
  // Beyond the outermost centres the edge texels hold.
  EXPECT_NEAR(t.at(0.0f, 1.0f).fog, 0.1f, 1e-6f);
}

TEST_F(render_surface_texture, FogIsMassOverCapacityClamped) {
  const fs::path file = dir_ / "surface_glass.0000.exr";
  // Over-full, half-full, and a texel outside every chart (all zero).
  test::write_surface_exr(file, 3, 1, {2e-6f, 1e-6f, 0}, {1e-6f, 2e-6f, 0}, {0, 0, 0});
  const SurfaceTexture t = SurfaceTexture::load(file);
  EXPECT_FLOAT_EQ(t.at(1 / 6.0f, 0.5f).fog, 1.0f);
  EXPECT_FLOAT_EQ(t.at(0.5f, 0.5f).fog, 0.5f);
  // Next to the empty texel the chart's own value holds, not a fade to dry.
  EXPECT_FLOAT_EQ(t.at(0.7f, 0.5f).fog, 0.5f);
}

TEST_F(render_surface_texture, MissingChannelIsAnErrorNamingFileAndChannel) {
  const fs::path file = dir_ / "surface_plate.0000.exr";
  test::write_rgb_exr(file, 1, 1, {Rgb::gray(1)});
  try {
    SurfaceTexture::load(file);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'mass'"), std::string::npos) << e.what();
  }
}

TEST(render_material, RoughnessFollowsFogThenWetting) {
  dp::io::Material mirror;
  mirror.type = dp::io::MaterialType::Conductor;
  mirror.roughness = 0.02;
  mirror.fogged_roughness = 0.5;
  mirror.wet_roughness = 0.01;
  mirror.wet_darkening = 0.4;
  const Material with_wet(mirror, true), without_wet(mirror, false);
  EXPECT_FLOAT_EQ(with_wet.roughness_at({0, 0}), 0.02f);
  EXPECT_FLOAT_EQ(with_wet.roughness_at({1, 0}), 0.5f);
  EXPECT_FLOAT_EQ(with_wet.roughness_at({0.25f, 0}), 0.75f * 0.02f + 0.25f * 0.5f);
  EXPECT_FLOAT_EQ(with_wet.roughness_at({3, 0}), 0.5f);  // clamped
  EXPECT_FLOAT_EQ(with_wet.roughness_at({1, 1}), 0.01f);
  EXPECT_FLOAT_EQ(without_wet.roughness_at({1, 1}), 0.5f);
  // The wet part reflects (1 - darkening) as much.
  EXPECT_NEAR(with_wet.bsdf_at({0, 1}).albedo().g, 0.6f * without_wet.bsdf_at({0, 1}).albedo().g, 1e-6f);
}

}  // namespace
}  // namespace dp::render
