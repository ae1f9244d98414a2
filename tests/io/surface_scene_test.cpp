// Scene keys of a rigid's surface textures (docs/scene-format.md) and the
// setup made from them: errors name the file and the key with what was
// expected and found.
#include <unistd.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene.h"
#include "simulation_setup.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

nlohmann::json demo_with_texture(const nlohmann::json& texture) {
  std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["simulation"]["rigids"][0]["texture"] = texture;
  return doc;
}

fs::path write_scene(const nlohmann::json& doc, const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("dewpoint-surface-scene-test-" + std::to_string(::getpid())) / "scenes";
  fs::create_directories(dir.parent_path() / "meshes");
  fs::create_directories(dir);
  fs::copy_file(fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj", dir.parent_path() / "meshes/tray.obj",
                fs::copy_options::overwrite_existing);
  fs::path file = dir / name;
  std::ofstream(file) << doc.dump(2);
  return file;
}

std::string error_of(const nlohmann::json& doc) {
  try {
    load_scene(write_scene(doc, "bad.json"));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SurfaceScene, TextureKeysAreRead) {
  Scene s = load_scene(write_scene(demo_with_texture({{"resolution", {64, 32}},
                                                      {"max_mass_kg_m2", 0.02},
                                                      {"initial_mass_kg_m2", 0.01},
                                                      {"wetting_decay_s", 0.5}}),
                                   "ok.json"));
  const auto& t = s.simulation.rigids[0].texture;
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->width, 64);
  EXPECT_EQ(t->height, 32);
  EXPECT_DOUBLE_EQ(t->max_mass_kg_m2, 0.02);
  EXPECT_DOUBLE_EQ(t->initial_mass_kg_m2, 0.01);
  EXPECT_DOUBLE_EQ(t->wetting_decay_s, 0.5);
  EXPECT_FALSE(load_scene(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json").simulation.rigids[0].texture.has_value());
}

TEST(SurfaceScene, ZeroResolutionIsAnErrorNamingTheKey) {
  const std::string e = error_of(demo_with_texture({{"resolution", {0, 512}}}));
  EXPECT_NE(e.find("bad.json: simulation.rigids[0].texture.resolution: expected two integers in [1, 16384] (texels), found [0, 512]"),
            std::string::npos)
      << e;
}

TEST(SurfaceScene, OtherBadTextureKeys) {
  EXPECT_NE(error_of(demo_with_texture({{"resolution", {8, 8}}, {"max_mass_kg_m2", -1}})).find("texture.max_mass_kg_m2: expected a non-negative number"),
            std::string::npos);
  EXPECT_NE(error_of(demo_with_texture({{"resolution", {8, 8}}, {"max_mass_image", "nowhere.png"}})).find("texture.max_mass_image: cannot read image file"),
            std::string::npos);
  EXPECT_NE(error_of(demo_with_texture({{"resolution", {8, 8}}, {"max_mass_image", "../meshes/tray.obj"}, {"max_mass_kg_m2", 1}}))
                .find("give either max_mass_kg_m2 or max_mass_image"),
            std::string::npos);
  EXPECT_NE(error_of(demo_with_texture({{"resolution", {8, 8}}, {"colour", 1}})).find("texture.colour: unknown key"), std::string::npos);
  EXPECT_NE(error_of(demo_with_texture({{"max_mass_kg_m2", 1}})).find("texture.resolution"), std::string::npos);
  nlohmann::json spaced = demo_with_texture({{"resolution", {8, 8}}});
  spaced["simulation"]["rigids"][0]["name"] = "my tray";
  spaced["render"]["objects"] = {{"my tray", {{"material", "tray"}}}};
  EXPECT_NE(error_of(spaced).find("rigids[0].name: a textured rigid's name may hold only"), std::string::npos);
}

TEST(SurfaceScene, SetupCarriesTheTexturesOfTexturedRigids) {
  Scene s = load_scene(write_scene(demo_with_texture({{"resolution", {128, 128}}, {"initial_mass_kg_m2", 0.01}}), "setup.json"));
  std::vector<RigidAtlas> atlases;
  SimulationSetup setup = make_simulation_setup(s, &atlases);
  ASSERT_EQ(setup.surfaces.size(), 1u);
  ASSERT_EQ(atlases.size(), 1u);
  EXPECT_EQ(atlases[0].rigid_name, "tray");
  const SurfaceTextureSetup& t = setup.surfaces[0];
  EXPECT_EQ(t.rigid_first, 0u);
  EXPECT_EQ(t.rigid_count, setup.rigid_position.size());
  EXPECT_EQ(t.texels.width, 128);
  double area = 0, max_mass = 0;
  for (std::size_t i = 0; i < t.texels.size(); ++i) area += t.texels.area[i], max_mass += t.texels.max_mass[i];
  EXPECT_NEAR(area, 0.84, 0.0084);
  EXPECT_NEAR(max_mass, 0.05 * area, 1e-6);  // the default 0.05 kg/m^2
  EXPECT_FLOAT_EQ(t.initial_mass_per_area, 0.01f);
  EXPECT_FLOAT_EQ(t.initial_temperature, 293.15f);
}

}  // namespace
}  // namespace dp::io
