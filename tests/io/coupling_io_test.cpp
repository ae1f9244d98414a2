// The scene's coupling section (docs/scene-format.md, simulation.coupling).
#include <unistd.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene.h"
#include "simulation_setup.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

fs::path scene_with_coupling(const nlohmann::json& coupling, const std::string& name) {
  std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["simulation"]["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
  doc["simulation"]["coupling"] = coupling;
  const fs::path dir = fs::temp_directory_path() / ("dewpoint-coupling-io-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << doc.dump(2);
  return dir / name;
}

TEST(coupling_Scene, ReadsEveryKeyIntoTheSetup) {
  const nlohmann::json c = {{"evaporation_a_kg_m2_s_pa", 2e-8}, {"evaporation_b_kg_m3_pa", 3e-8}, {"phase_change_time_scale", 50}, {"heat_exchange", false},
                            {"particle_evaporation", false}, {"texel_exchange", false}, {"particle_emission", false}, {"latent_heat", true}, {"latent_heat_j_kg", 2.4e6},
                            {"path_force", true}, {"path_adhesion", 3.5}, {"air_density_kg_m3", 1.1}, {"air_specific_heat_j_kgk", 1000}, {"air_conductivity_w_mk", 0.03}};
  const SimulationSetup s = make_simulation_setup(load_scene(scene_with_coupling(c, "all.json")));
  EXPECT_DOUBLE_EQ(s.coupling.coefficients.a, 2e-8);
  EXPECT_DOUBLE_EQ(s.coupling.coefficients.b, 3e-8);
  EXPECT_DOUBLE_EQ(s.coupling.phase_change_time_scale, 50);
  EXPECT_DOUBLE_EQ(s.coupling.rate_coefficients().a, 50 * 2e-8);
  EXPECT_DOUBLE_EQ(s.coupling.rate_coefficients().b, 50 * 3e-8);
  EXPECT_FALSE(s.coupling.heat_exchange);
  EXPECT_FALSE(s.coupling.particle_evaporation);
  EXPECT_FALSE(s.coupling.texel_exchange);
  EXPECT_FALSE(s.coupling.particle_emission);
  EXPECT_TRUE(s.coupling.latent_heat);
  EXPECT_FLOAT_EQ(s.coupling.latent_heat_j_kg, 2.4e6f);
  EXPECT_TRUE(s.coupling.path_force);
  EXPECT_FLOAT_EQ(s.coupling.path_adhesion, 3.5f);
  EXPECT_FLOAT_EQ(s.coupling.air.density, 1.1f);
  EXPECT_FLOAT_EQ(s.coupling.air.specific_heat, 1000.0f);
  EXPECT_FLOAT_EQ(s.coupling.air.conductivity, 0.03f);
}

TEST(coupling_Scene, BadValuesNameTheirKeys) {
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"evaporation_a_kg_m2_s_pa", -1}, {"phase_change_time_scale", 0}, {"air_density_kg_m3", 0}, {"heat_exchange", "yes"}, {"latent_heat_j_kg", 0}, {"path_adhesion", -1},
           {"path_forces", true}}) {
    std::string what;
    try {
      load_scene(scene_with_coupling({{key, value}}, "bad.json"));
    } catch (const SceneError& e) {
      what = e.what();
    }
    EXPECT_NE(what.find(key), std::string::npos) << key << ": " << what;
  }
}

}  // namespace
}  // namespace dp::io
