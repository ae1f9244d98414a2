// dewpoint-render end to end on the demo scene, shrunk to 32x24 pixels and
// a few samples: frames folder and liquid meshes are made here.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "../test_folder.h"
#include "frames.h"
#include "ply.h"
#include "test_meshes.h"
#include "test_textures.h"

namespace fs = std::filesystem;

namespace dp::render {
namespace {

const fs::path kDemoScene = fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json";

struct RunResult {
  int exit_code;
  std::string stderr_text;
};

struct ExrImage {
  int width = 0, height = 0, channels = 0;
  std::vector<std::string> names;
  std::vector<float> pixels;
  float at(int x, int y, int c) const { return pixels[static_cast<std::size_t>((y * width + x) * channels + c)]; }
};

class render_cli : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = dp::test::test_folder("dewpoint_render_cli_" + std::to_string(::getpid()) + "_");
    fs::remove_all(root_);
    fs::create_directories(root_ / "frames");
    fs::create_directories(root_ / "meshes");
  }
  void TearDown() override { fs::remove_all(root_); }

  void write_frames(const std::vector<int>& indices) {
    dp::io::FramesManifest m;
    m.scene_file = kDemoScene;
    m.scene_name = "demo";
    m.particle_spacing_m = 0.0125;
    m.particle_radius_m = 0.00625;
    m.rigid_particles_file = "rigid_particles.ply";
    for (int i : indices) m.frames.push_back({i, i / 12.0, 600 * i, 1000, dp::io::frame_file_name("particles", i, "ply")});
    dp::io::write_manifest(root_ / "frames", m);
  }

  void write_liquid(int frame, std::array<float, 3> centre) {
    dp::io::write_ply(root_ / "meshes" / dp::io::frame_file_name("liquid", frame, "ply"),
                      test::liquid_ply(test::icosphere(centre, 0.1f, 3)));
  }

  RunResult render(const std::string& extra_arguments, bool quiet = true) {
    const fs::path log = root_ / "stderr.txt";
    const std::string command = std::string(DEWPOINT_RENDER_EXE) + " " + kDemoScene.string() + " --frames-dir " +
                                (root_ / "frames").string() + " --meshes-dir " + (root_ / "meshes").string() + " -o " +
                                (root_ / "out").string() + " --spp 4 --resolution 32x24 " + (quiet ? "--quiet " : "") + extra_arguments +
                                " 2> " + log.string();
    const int status = std::system(command.c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
  }

  ExrImage read_exr(const fs::path& file) {
    ExrImage image;
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
      ADD_FAILURE() << "OpenImageIO cannot open " << file << ": " << OIIO::geterror();
      return image;
    }
    const OIIO::ImageSpec& spec = in->spec();
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.names = spec.channelnames;
    image.pixels.resize(static_cast<std::size_t>(spec.width * spec.height * spec.nchannels));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()));
    return image;
  }

  fs::path out(const std::string& name) const { return root_ / "out" / name; }

  fs::path root_;
};

TEST_F(render_cli, WritesImagesWhereTheLiquidShows) {
  // Frame 1's liquid is far behind the camera: the same picture without it.
  write_frames({0, 1});
  write_liquid(0, {0, 0.1f, 0});
  write_liquid(1, {5, 5, 5});
  const RunResult run = render("");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  for (const char* name : {"beauty.0000.exr", "beauty.0000.png", "beauty.0000.json", "beauty.0001.exr"})
    EXPECT_TRUE(fs::exists(out(name))) << name;

  const ExrImage with_liquid = read_exr(out("beauty.0000.exr"));
  const ExrImage without = read_exr(out("beauty.0001.exr"));
  ASSERT_EQ(with_liquid.width, 32);
  ASSERT_EQ(with_liquid.height, 24);
  ASSERT_EQ(with_liquid.channels, 11);  // RGBA, albedo, normal, depth
  ASSERT_EQ(without.pixels.size(), with_liquid.pixels.size());
  for (int y = 0; y < with_liquid.height; ++y)
    for (int x = 0; x < with_liquid.width; ++x)
      for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(with_liquid.at(x, y, c)) && with_liquid.at(x, y, c) >= 0);

  // The drop sits at the centre of the view (the camera looks at 6 cm above the floor).
  double centre_difference = 0;
  for (int y = 9; y < 15; ++y)
    for (int x = 13; x < 19; ++x)
      for (int c = 0; c < 3; ++c) centre_difference += std::abs(with_liquid.at(x, y, c) - without.at(x, y, c));
  EXPECT_GT(centre_difference / (6 * 6 * 3), 0.05);

  std::ifstream sidecar(out("beauty.0000.json"));
  const auto record = nlohmann::json::parse(sidecar);
  EXPECT_EQ(record.at("spp"), 4);
  EXPECT_EQ(record.at("resolution"), nlohmann::json::array({32, 24}));
  EXPECT_EQ(record.at("scene_file"), kDemoScene.lexically_normal().string());
  for (const char* key : {"render_time_s", "samples_per_s", "seed", "generator"}) EXPECT_TRUE(record.contains(key)) << key;
}

TEST_F(render_cli, ThreadCountDoesNotChangeTheImage) {
  write_frames({0});
  write_liquid(0, {0, 0.1f, 0});
  ASSERT_EQ(render("--threads 1").exit_code, 0);
  const ExrImage one = read_exr(out("beauty.0000.exr"));
  ASSERT_EQ(render("--threads 2").exit_code, 0);
  const ExrImage two = read_exr(out("beauty.0000.exr"));
  EXPECT_EQ(one.pixels, two.pixels);
}

TEST_F(render_cli, MissingMeshIsAnErrorNamingTheFile) {
  write_frames({0, 2});
  write_liquid(0, {0, 0.1f, 0});
  const RunResult run = render("");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("dewpoint-render: "), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("liquid.0002.ply"), std::string::npos) << run.stderr_text;
  EXPECT_FALSE(fs::exists(out("beauty.0000.exr"))) << "inputs are checked before any frame is rendered";
}

TEST_F(render_cli, BadResolutionIsAnError) {
  write_frames({0});
  write_liquid(0, {0, 0.1f, 0});
  const RunResult run = render("--resolution 32by24");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("--resolution"), std::string::npos) << run.stderr_text;
}

TEST_F(render_cli, AovChannelsAreNamedAndSelectable) {
  write_frames({0});
  write_liquid(0, {0, 0.1f, 0});
  ASSERT_EQ(render("").exit_code, 0);
  const ExrImage all = read_exr(out("beauty.0000.exr"));
  for (const char* name : {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "Z"})
    EXPECT_NE(std::find(all.names.begin(), all.names.end(), name), all.names.end()) << name;
  // The camera looks down at the tray: depth is finite and positive, normals unit.
  const auto channel = [&](const char* name) {
    return static_cast<int>(std::find(all.names.begin(), all.names.end(), name) - all.names.begin());
  };
  const float depth = all.at(16, 20, channel("Z"));
  EXPECT_TRUE(std::isfinite(depth) && depth > 0) << depth;
  const float nx = all.at(16, 20, channel("normal.X")), ny = all.at(16, 20, channel("normal.Y")), nz = all.at(16, 20, channel("normal.Z"));
  EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0f, 0.05f);

  ASSERT_EQ(render("--aov depth").exit_code, 0);
  EXPECT_EQ(read_exr(out("beauty.0000.exr")).channels, 5);
  ASSERT_EQ(render("--aov none").exit_code, 0);
  EXPECT_EQ(read_exr(out("beauty.0000.exr")).channels, 4);
  const RunResult bad = render("--aov albedo,speed");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.stderr_text.find("--aov"), std::string::npos) << bad.stderr_text;
  EXPECT_NE(bad.stderr_text.find("speed"), std::string::npos) << bad.stderr_text;
}

TEST_F(render_cli, ReportsProgressWithEta) {
  write_frames({0, 1});
  write_liquid(0, {0, 0.1f, 0});
  write_liquid(1, {0, 0.1f, 0});
  const RunResult run = render("", false);
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  // Frames done of frames; not a terminal, so at most one line per frame.
  EXPECT_NE(run.stderr_text.find("render demo 2/2 "), std::string::npos) << run.stderr_text;
  EXPECT_EQ(run.stderr_text.find("render demo 0/2 "), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("ETA"), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("samples/s"), std::string::npos) << run.stderr_text;
}

TEST_F(render_cli, RigidAtlasAndSurfaceTextureAreUsedWhenPresent) {
  write_frames({0, 1});
  write_liquid(0, {0, 0.1f, 0});
  write_liquid(1, {0, 0.1f, 0});
  dp::io::write_ply(root_ / "frames" / "rigid_tray.ply", test::rigid_atlas_ply(test::textured_square(-0.2f, 0.2f, -0.2f, 0.2f, 0)));
  test::write_surface_exr(root_ / "frames" / "surface_tray.0001.exr", 2, 2, {0, 1e-6f, 0, 0}, {1e-6f, 1e-6f, 1e-6f, 1e-6f}, {0, 0, 0, 0});
  const RunResult run = render("");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::ifstream frame0(out("beauty.0000.json")), frame1(out("beauty.0001.json"));
  EXPECT_TRUE(nlohmann::json::parse(frame0).at("surface_textures").empty());  // no texture for frame 0: dry
  const auto textures = nlohmann::json::parse(frame1).at("surface_textures");
  ASSERT_EQ(textures.size(), 1u);
  EXPECT_NE(textures[0].get<std::string>().find("surface_tray.0001.exr"), std::string::npos);
}

TEST_F(render_cli, BrokenSurfaceTextureIsAnErrorNamingTheFile) {
  write_frames({0});
  write_liquid(0, {0, 0.1f, 0});
  dp::io::write_ply(root_ / "frames" / "rigid_tray.ply", test::rigid_atlas_ply(test::textured_square(-0.2f, 0.2f, -0.2f, 0.2f, 0)));
  test::write_rgb_exr(root_ / "frames" / "surface_tray.0000.exr", 1, 1, {Rgb::gray(1)});
  const RunResult run = render("");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("surface_tray.0000.exr"), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("mass"), std::string::npos) << run.stderr_text;
}

}  // namespace
}  // namespace dp::render
