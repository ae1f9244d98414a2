// The scene file's render section: new keys read with their defaults, and
// bad values rejected with the file, the key's full path, what was
// expected and what was found.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "scene.h"

namespace fs = std::filesystem;

namespace dp::render {
namespace {

class render_settings : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = fs::temp_directory_path() / ("dewpoint_render_settings_" + std::to_string(::getpid()) + ".json");
  }
  void TearDown() override { fs::remove(file_); }

  // The demo scene with its render section replaced by `render`.
  dp::io::Scene load(const std::string& render) {
    std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
    nlohmann::json scene = nlohmann::json::parse(in);
    scene["simulation"]["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
    scene["render"] = nlohmann::json::parse(render);
    std::ofstream(file_) << scene.dump();
    return dp::io::load_scene(file_);
  }

  std::string error_of(const std::string& render) {
    try {
      load(render);
    } catch (const dp::io::SceneError& e) {
      return e.what();
    }
    return "";
  }

  fs::path file_;
};

const char* kBase = R"({"resolution": [64, 48], "camera": {"position_m": [0, 1, 2], "look_at_m": [0, 0, 0]},
  "materials": {"water": {"type": "dielectric"}, "tray": {"type": "diffuse"}}, "objects": {"tray": {"material": "tray"}})";

std::string with(const std::string& extra) { return std::string(kBase) + ", " + extra + "}"; }

TEST_F(render_settings, NewKeysAndTheirDefaults) {
  const dp::io::Scene defaults = load(std::string(kBase) + "}");
  EXPECT_EQ(defaults.render.camera.model, dp::io::CameraModel::Pinhole);
  EXPECT_EQ(defaults.render.filter.type, dp::io::FilterType::Gaussian);
  EXPECT_EQ(defaults.render.environment.type, dp::io::EnvironmentType::Sky);
  EXPECT_TRUE(defaults.render.aovs.albedo && defaults.render.aovs.normal && defaults.render.aovs.depth);
  EXPECT_TRUE(defaults.render.wet_paths);
  EXPECT_EQ(defaults.render.sampler, dp::io::SamplerType::Sobol);

  nlohmann::json render = nlohmann::json::parse(std::string(kBase) + "}");
  render["materials"]["tray"] = {{"type", "conductor"}, {"roughness", 0.01}, {"fogged_roughness", 0.6}, {"wet_roughness", 0.0}, {"wet_darkening", 0.3}};
  render["materials"]["lamp"] = {{"type", "diffuse"}, {"emission_rgb", {4, 4, 4}}};
  render["filter"] = {{"type", "tent"}, {"radius_px", 2}};
  render["environment"] = {{"type", "map"}, {"file", "sky.exr"}, {"rotation_deg", 90}, {"intensity", 2}};
  render["aovs"] = "depth";
  render["wet_paths"] = false;
  const dp::io::Scene s = load(render.dump());
  const dp::io::Material& tray = s.render.materials.at("tray");
  EXPECT_EQ(tray.type, dp::io::MaterialType::Conductor);
  EXPECT_DOUBLE_EQ(tray.albedo[0], 1);  // an untinted conductor
  EXPECT_DOUBLE_EQ(tray.fogged_roughness, 0.6);
  EXPECT_DOUBLE_EQ(tray.wet_darkening, 0.3);
  EXPECT_DOUBLE_EQ(s.render.materials.at("lamp").emission[1], 4);
  EXPECT_EQ(s.render.filter.type, dp::io::FilterType::Tent);
  EXPECT_DOUBLE_EQ(s.render.filter.radius_px, 2);
  EXPECT_EQ(s.render.environment.map, file_.parent_path() / "sky.exr");  // relative to the scene file
  EXPECT_FALSE(s.render.aovs.albedo);
  EXPECT_TRUE(s.render.aovs.depth);
  EXPECT_FALSE(s.render.wet_paths);
}

TEST_F(render_settings, ThinLensNeedsAnAperture) {
  const std::string e = error_of(R"({"resolution": [64, 48], "camera": {"model": "thin_lens", "position_m": [0, 1, 2], "look_at_m": [0, 0, 0]},
    "materials": {"water": {"type": "dielectric"}, "tray": {"type": "diffuse"}}, "objects": {"tray": {"material": "tray"}}})");
  EXPECT_NE(e.find("render.camera.aperture_radius_m"), std::string::npos) << e;
}

TEST_F(render_settings, BadValuesNameTheKey) {
  EXPECT_NE(error_of(with(R"("filter": {"type": "mitchell"})")).find("render.filter.type"), std::string::npos);
  EXPECT_NE(error_of(with(R"("sampler": "halton")")).find("render.sampler"), std::string::npos);
  EXPECT_NE(error_of(with(R"("environment": {"type": "map"})")).find("render.environment.file"), std::string::npos);
  EXPECT_NE(error_of(with(R"("aovs": "albedo,velocity")")).find("velocity"), std::string::npos);
  nlohmann::json rough_water = nlohmann::json::parse(std::string(kBase) + "}");
  rough_water["materials"]["water"]["roughness"] = 1.5;
  const std::string rough = error_of(rough_water.dump());
  EXPECT_NE(rough.find("render.materials.water.roughness"), std::string::npos) << rough;
  EXPECT_NE(rough.find("1.5"), std::string::npos) << rough;
  EXPECT_NE(error_of(with(R"("environment": {"type": "sky", "radiance_rgb": [1, 1, 1]})")).find("radiance_rgb"), std::string::npos);
}

}  // namespace
}  // namespace dp::render
