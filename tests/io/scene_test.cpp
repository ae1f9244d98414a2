// Scene validation: every error names the file and the key, with what was
// expected and what was found.
#include <unistd.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene.h"
#include "simulation_setup.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

const fs::path kDemo = fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json";

nlohmann::json demo_document() {
  std::ifstream in(kDemo);
  return nlohmann::json::parse(in);
}

// Writes the document beside the demo scene so relative mesh paths resolve.
fs::path write_scene(const nlohmann::json& doc, const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("dewpoint-scene-test-" + std::to_string(::getpid())) / "scenes";
  fs::create_directories(dir);
  fs::create_directories(dir.parent_path() / "meshes");
  fs::copy_file(fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj", dir.parent_path() / "meshes/tray.obj",
                fs::copy_options::overwrite_existing);
  fs::path file = dir / name;
  std::ofstream(file) << doc.dump(2);
  return file;
}

std::string error_of(const nlohmann::json& doc, const std::string& name) {
  fs::path file = write_scene(doc, name);
  try {
    load_scene(file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, DemoLoads) {
  Scene s = load_scene(kDemo);
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.simulation.rigids.size(), 1u);
  EXPECT_TRUE(fs::exists(s.simulation.rigids[0].mesh));
  EXPECT_DOUBLE_EQ(s.simulation.liquid.temperature_k, 293.15);
  EXPECT_EQ(s.render.rigid_material.at("tray"), "tray");
}

TEST(Scene, UnknownKeyIsNamedWithItsPath) {
  auto doc = demo_document();
  doc["simulation"]["liquid"]["viscosity"] = 0.1;  // the key is xsph_epsilon
  std::string e = error_of(doc, "unknown_key.json");
  EXPECT_NE(e.find("unknown_key.json"), std::string::npos) << e;
  EXPECT_NE(e.find("simulation.liquid.viscosity: unknown key"), std::string::npos) << e;
}

// The two keys that switch new outputs and physics on: read as given,
// refused with their path when of the wrong kind.
TEST(Scene, LevelSetAndViscosityKeys) {
  auto doc = demo_document();
  EXPECT_FALSE(load_scene(write_scene(doc, "defaults.json")).mesh.level_set);
  EXPECT_DOUBLE_EQ(load_scene(write_scene(doc, "defaults.json")).simulation.liquid.kinematic_viscosity_m2_s, 1e-6);
  doc["mesh"]["level_set"] = true;
  doc["simulation"]["liquid"]["kinematic_viscosity_m2_s"] = 1e-3;
  const Scene s = load_scene(write_scene(doc, "set.json"));
  EXPECT_TRUE(s.mesh.level_set);
  EXPECT_DOUBLE_EQ(s.simulation.liquid.kinematic_viscosity_m2_s, 1e-3);
  doc["mesh"]["level_set"] = "yes";
  EXPECT_NE(error_of(doc, "bad_level_set.json").find("mesh.level_set"), std::string::npos);
  doc["mesh"]["level_set"] = false;
  doc["simulation"]["liquid"]["kinematic_viscosity_m2_s"] = -1;
  EXPECT_NE(error_of(doc, "bad_nu.json").find("simulation.liquid.kinematic_viscosity_m2_s"), std::string::npos);
}

TEST(Scene, PressureSolverMethodKeys) {
  auto doc = demo_document();
  EXPECT_EQ(load_scene(write_scene(doc, "defaults.json")).simulation.pressure_solver.method, "pcisph");
  doc["simulation"]["pressure_solver"] = {{"method", "dfsph"}, {"max_divergence_error", 0.002}};
  const Scene s = load_scene(write_scene(doc, "dfsph.json"));
  EXPECT_EQ(s.simulation.pressure_solver.method, "dfsph");
  EXPECT_DOUBLE_EQ(s.simulation.pressure_solver.max_divergence_error, 0.002);
  EXPECT_EQ(make_simulation_setup(s).pressure.method, dp::PressureSolverMethod::Dfsph);
  doc["simulation"]["pressure_solver"]["warm_start"] = true;
  EXPECT_NE(error_of(doc, "dfsph_warm.json").find("simulation.pressure_solver.warm_start"), std::string::npos);
  doc["simulation"]["pressure_solver"] = {{"method", "iisph"}};
  const std::string e = error_of(doc, "bad_method.json");
  EXPECT_NE(e.find("simulation.pressure_solver.method: expected \"pcisph\" or \"dfsph\", found \"iisph\""), std::string::npos) << e;
}

// The scenes take their wall shear from the law of the wall unless asked.
TEST(Scene, WallShearKeys) {
  auto doc = demo_document();
  const Scene defaults = load_scene(write_scene(doc, "defaults.json"));
  EXPECT_EQ(defaults.simulation.liquid.wall_shear, "spalding1961");
  EXPECT_EQ(make_simulation_setup(defaults).liquid.wall_shear, dp::WallShear::Spalding1961);
  doc["simulation"]["liquid"]["wall_shear"] = "no_slip";
  EXPECT_EQ(make_simulation_setup(load_scene(write_scene(doc, "no_slip.json"))).liquid.wall_shear, dp::WallShear::NoSlip);
  doc["simulation"]["liquid"]["wall_shear"] = "log_law";
  const std::string e = error_of(doc, "bad_wall.json");
  EXPECT_NE(e.find("simulation.liquid.wall_shear: expected \"no_slip\" or \"spalding1961\", found \"log_law\""),
            std::string::npos)
      << e;
}

// Leaving the domain stops the run unless the scene lets particles go.
TEST(Scene, DomainLeavingKey) {
  auto doc = demo_document();
  EXPECT_EQ(make_simulation_setup(load_scene(write_scene(doc, "defaults.json"))).leaving, dp::DomainLeaving::Stop);
  doc["simulation"]["domain"]["leaving"] = "remove";
  EXPECT_EQ(make_simulation_setup(load_scene(write_scene(doc, "remove.json"))).leaving, dp::DomainLeaving::Remove);
  doc["simulation"]["domain"]["leaving"] = "delete";
  const std::string e = error_of(doc, "bad_leaving.json");
  EXPECT_NE(e.find("simulation.domain.leaving: expected \"stop\" or \"remove\", found \"delete\""), std::string::npos) << e;
}

TEST(Scene, WrongTypeNamesExpectedAndFound) {
  auto doc = demo_document();
  doc["simulation"]["time_step_s"] = "fast";
  std::string e = error_of(doc, "wrong_type.json");
  EXPECT_NE(e.find("simulation.time_step_s: expected a number, found a string"), std::string::npos) << e;
}

TEST(Scene, MissingMeshNamesTheKeyAndTheFile) {
  auto doc = demo_document();
  doc["simulation"]["rigids"][0]["mesh"] = "../meshes/no_such_tray.obj";
  std::string e = error_of(doc, "missing_mesh.json");
  EXPECT_NE(e.find("simulation.rigids[0].mesh"), std::string::npos) << e;
  EXPECT_NE(e.find("no_such_tray.obj"), std::string::npos) << e;
}

TEST(Scene, MissingRequiredKey) {
  auto doc = demo_document();
  doc["simulation"].erase("particle_spacing_m");
  std::string e = error_of(doc, "missing_key.json");
  EXPECT_NE(e.find("simulation.particle_spacing_m: missing required key"), std::string::npos) << e;
}

TEST(Scene, UnknownTimeStepModeIsRejected) {
  auto doc = demo_document();
  doc["simulation"]["time_step_mode"] = "adaptive";
  std::string e = error_of(doc, "mode.json");
  EXPECT_NE(e.find("simulation.time_step_mode: expected \"cfl\" or \"fixed\", found \"adaptive\""), std::string::npos) << e;
}

TEST(Scene, SettleReadsItsKeysAndRefusesANegativeDuration) {
  auto doc = demo_document();
  doc["simulation"]["settle"] = {{"duration_s", 0.25}, {"damping_per_s", 40}};
  Scene s = load_scene(write_scene(doc, "settle.json"));
  EXPECT_DOUBLE_EQ(s.simulation.settle.duration_s, 0.25);
  EXPECT_DOUBLE_EQ(s.simulation.settle.damping_per_s, 40);
  EXPECT_DOUBLE_EQ(load_scene(kDemo).simulation.settle.duration_s, 0.0) << "no settling unless asked";
  doc["simulation"]["settle"]["duration_s"] = -1;
  std::string e = error_of(doc, "settle_negative.json");
  EXPECT_NE(e.find("settle_negative.json"), std::string::npos) << e;
  EXPECT_NE(e.find("simulation.settle.duration_s"), std::string::npos) << e;
}

TEST(Scene, TemperatureBelowAbsoluteZeroIsRejected) {
  auto doc = demo_document();
  doc["simulation"]["liquid"]["temperature_c"] = -300;
  std::string e = error_of(doc, "cold.json");
  EXPECT_NE(e.find("simulation.liquid.temperature_c: temperature below absolute zero"), std::string::npos) << e;
}

TEST(Scene, LiquidOutsideTheDomainIsRejected) {
  auto doc = demo_document();
  doc["simulation"]["liquid_blocks"][0]["max_m"] = {0.1, 0.9, 0.1};
  std::string e = error_of(doc, "outside.json");
  EXPECT_NE(e.find("simulation.liquid_blocks[0].max_m: outside the simulation domain"), std::string::npos) << e;
}

TEST(Scene, RigidWithoutRenderMaterialIsRejected) {
  auto doc = demo_document();
  doc["render"]["objects"].erase("tray");
  std::string e = error_of(doc, "no_material.json");
  EXPECT_NE(e.find("render.objects: has no entry for rigid 'tray'"), std::string::npos) << e;
}

TEST(Scene, InvalidJsonNamesTheFile) {
  fs::path file = fs::temp_directory_path() / ("dewpoint-scene-test-" + std::to_string(::getpid())) / "broken.json";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "{ \"name\": ";
  try {
    load_scene(file);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: not valid JSON"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dp::io
