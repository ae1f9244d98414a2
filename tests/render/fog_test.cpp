// A steamed mirror (the paper's SCA-logo scene, Sec. 8): as condensed water
// fills the mirror's mass texture, its roughness grows and the checkerboard
// it reflects blurs. Image gradient energy, a standard sharpness measure,
// must fall monotonically with the mass. The mirror, its atlas and its
// textures go through the same files and loaders as a simulated frame.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "../test_folder.h"
#include "frames.h"
#include "image_environment.h"
#include "ply.h"
#include "render_image.h"
#include "scene_objects.h"
#include "test_meshes.h"
#include "test_textures.h"

namespace fs = std::filesystem;

namespace dp::render {
namespace {

constexpr int kTexture = 8;

class render_fog : public ::testing::Test {
 protected:
  void SetUp() override {
    frames_ = dp::test::test_folder("dewpoint_render_fog_" + std::to_string(::getpid()) + "_");
    fs::create_directories(frames_);
    dp::io::write_ply(rigid_atlas_file(frames_, "mirror"), test::rigid_atlas_ply(test::textured_square(-1, 1, -1, 1, 0)));

    dp::io::Material mirror;
    mirror.type = dp::io::MaterialType::Conductor;
    mirror.albedo = {1, 1, 1};
    mirror.roughness = 0;
    mirror.fogged_roughness = 0.5;
    mirror.wet_roughness = 0;
    mirror.wet_darkening = 0.5;
    io::RigidObject rigid;
    rigid.name = "mirror";
    rigid.mesh = frames_ / "not-used.obj";
    scene_.simulation.rigids.push_back(rigid);
    scene_.render.materials["mirror"] = mirror;
    scene_.render.rigid_material["mirror"] = "mirror";
    settings_.width = settings_.height = 48;
    settings_.spp = 128;
    settings_.max_depth = 4;
    settings_.camera.position_m = {0, 0, 2.2};
    settings_.camera.look_at_m = {0, 0, 0};
    settings_.camera.fov_deg = 40;
  }
  void TearDown() override { fs::remove_all(frames_); }

  // Fog fraction per texel (mass over a capacity of 1e-6 kg) and wetting.
  void write_texture(int frame, const std::vector<float>& fog, const std::vector<float>& wetting) {
    std::vector<float> mass, capacity(fog.size(), 1e-6f);
    for (float f : fog) mass.push_back(f * 1e-6f);
    test::write_surface_exr(surface_texture_file(frames_, "mirror", frame), kTexture, kTexture, mass, capacity, wetting);
  }

  // A black-and-white checkerboard all around, 22.5 degrees a square.
  static ImageEnvironment checkerboard() {
    const int w = 128, h = 64;
    std::vector<Rgb> pixels;
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) pixels.push_back(((row / 8 + col / 8) % 2) ? Rgb::gray(1) : Rgb::gray(0.05f));
    return ImageEnvironment(pixels, w, h, 1, 0);
  }

  RenderedImage render(int frame, bool wet_paths, int threads = 0) {
    std::vector<SceneObject> objects = load_rigid_objects(scene_, frames_);
    EXPECT_EQ(attach_surface_textures(objects, frames_, frame).size(), 1u);
    const RenderScene scene(objects, wet_paths);
    return render_image(scene, checkerboard(), settings_, threads);
  }

  // Sum of squared differences between neighbouring 2x2 block means (the
  // blocks keep edges and average away most of the sampling noise), over
  // pixel columns [x0, x1).
  static double gradient_energy(const Image& image, int x0, int x1) {
    const auto block = [&](int bx, int by) {
      return 0.25 * (image.at(2 * bx, 2 * by).g + image.at(2 * bx + 1, 2 * by).g + image.at(2 * bx, 2 * by + 1).g +
                     image.at(2 * bx + 1, 2 * by + 1).g);
    };
    double e = 0;
    for (int by = 0; by + 1 < image.height / 2; ++by)
      for (int bx = x0 / 2; bx + 1 < x1 / 2; ++bx) {
        const double g = block(bx, by);
        e += (block(bx + 1, by) - g) * (block(bx + 1, by) - g) + (block(bx, by + 1) - g) * (block(bx, by + 1) - g);
      }
    return e;
  }

  fs::path frames_;
  dp::io::Scene scene_;
  dp::io::RenderSettings settings_;
};

TEST_F(render_fog, GrowingMassBlursTheReflection) {
  const std::vector<float> fractions{0, 0.1f, 0.25f, 0.5f, 1};
  std::vector<double> energy;
  for (std::size_t f = 0; f < fractions.size(); ++f) {
    write_texture(static_cast<int>(f), std::vector<float>(kTexture * kTexture, fractions[f]), std::vector<float>(kTexture * kTexture, 0));
    energy.push_back(gradient_energy(render(static_cast<int>(f), true).beauty, 0, settings_.width));
    std::printf("m/m_max %.2f (alpha %.3f): gradient energy %.3f\n", fractions[f], 0.5 * fractions[f], energy.back());
  }
  for (std::size_t i = 1; i < energy.size(); ++i) EXPECT_LT(energy[i], energy[i - 1]) << "m/m_max " << fractions[i];
  EXPECT_LT(energy.back(), 0.25 * energy.front());
}

TEST_F(render_fog, WetPathsClearTheFogWhereSwitchedOn) {
  // Fully fogged; a drop has run down the left half (texture columns 0-3).
  std::vector<float> wetting(kTexture * kTexture, 0);
  for (int row = 0; row < kTexture; ++row)
    for (int col = 0; col < kTexture / 2; ++col) wetting[static_cast<std::size_t>(row * kTexture + col)] = 1;
  write_texture(0, std::vector<float>(kTexture * kTexture, 1), wetting);
  // The mirror spans the middle 2/3 of the picture; compare its halves, away from the seam.
  const int left0 = 10, left1 = 20, right0 = 28, right1 = 38;
  scene_.render.materials["mirror"].wet_darkening = 0;
  const Image on = render(0, true).beauty, off = render(0, false).beauty;
  const double on_ratio = gradient_energy(on, left0, left1) / gradient_energy(on, right0, right1);
  const double off_ratio = gradient_energy(off, left0, left1) / gradient_energy(off, right0, right1);
  std::printf("gradient energy left/right: wet paths on %.2f, off %.2f\n", on_ratio, off_ratio);
  EXPECT_GT(on_ratio, 3.0);
  EXPECT_LT(off_ratio, 1.5);
  EXPECT_GT(off_ratio, 1 / 1.5);

  // Darkening scales what the wet part reflects.
  scene_.render.materials["mirror"].wet_darkening = 0.5;
  const Image darker = render(0, true).beauty;
  double clear_sum = 0, darker_sum = 0;
  for (int y = 10; y < 38; ++y)
    for (int x = left0; x < left1; ++x) clear_sum += on.at(x, y).g, darker_sum += darker.at(x, y).g;
  EXPECT_NEAR(darker_sum / clear_sum, 0.5, 0.02);
}

TEST_F(render_fog, TexturedSceneIsTheSameForAnyThreadCount) {
  std::vector<float> fog(kTexture * kTexture);
  for (std::size_t i = 0; i < fog.size(); ++i) fog[i] = static_cast<float>(i) / static_cast<float>(fog.size());
  write_texture(0, fog, std::vector<float>(kTexture * kTexture, 0.3f));
  settings_.spp = 8;
  const RenderedImage one = render(0, true, 1), two = render(0, true, 2);
  EXPECT_EQ(std::memcmp(one.beauty.pixels.data(), two.beauty.pixels.data(), one.beauty.pixels.size() * sizeof(Rgb)), 0);
}

}  // namespace
}  // namespace dp::render
