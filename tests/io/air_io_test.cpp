// The scene's air section (docs/scene-format.md) and the air frame's OpenVDB
// file (docs/file-formats.md).
#include <unistd.h>
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <filesystem>
#include <fstream>

#include "air_vdb.h"
#include "scene.h"
#include "simulation_setup.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

nlohmann::json scene_with_air(const nlohmann::json& air) {
  std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["simulation"]["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
  doc["simulation"]["air"] = air;
  return doc;
}

fs::path write_scene(const nlohmann::json& doc, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("dewpoint-air-io-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << doc.dump(2);
  return file;
}

std::string error_of(const nlohmann::json& air, const std::string& name) {
  try {
    load_scene(write_scene(scene_with_air(air), name));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// The demo's domain is 0.7 m wide and h = 2 x 0.0125 m: cells must exceed
// 0.05 m, so at most 13 cells along the longest axis.
TEST(air_Scene, ReadsEveryKey) {
  const nlohmann::json air = {
      {"resolution", 12},
      {"temperature_c", 25},
      {"relative_humidity", 0.5},
      {"buoyancy_alpha", 1.5},
      {"buoyancy_beta", 0.04},
      {"vorticity_epsilon", 2},
      {"vapor_diffusivity_m2_s", 3e-5},
      {"heat_diffusivity_m2_s", 2e-5},
      {"advection", "maccormack"},
      {"boundary", {{"x_max", "open"}, {"y_max", "open"}}},
      {"inflows",
       {{{"shape", "disc"}, {"center_m", {-0.3, 0.3, 0}}, {"normal", {2, 0, 0}}, {"radius_m", 0.1},
         {"velocity_m_s", {1, 0, 0}}, {"temperature_c", 35}, {"vapor_kg_m3", 0.02}},
        {{"shape", "box"}, {"min_m", {0, 0, 0}}, {"max_m", {0.1, 0.1, 0.1}}}}},
      {"projection", {{"tolerance", 1e-6}, {"max_iterations", 50}}}};
  const Scene s = load_scene(write_scene(scene_with_air(air), "all_keys.json"));
  ASSERT_TRUE(s.simulation.air.has_value());
  const AirSettings a = make_air_settings(*s.simulation.air);
  EXPECT_EQ(a.resolution, 12);
  EXPECT_FLOAT_EQ(a.ambient_temperature, 298.15f);
  // 50 % of saturation at 25 C: 0.5 x 3169 Pa / (461.5 x 298.15) = 11.5 g/m^3.
  EXPECT_NEAR(a.ambient_vapor, 0.0115, 0.0002);
  EXPECT_FLOAT_EQ(a.buoyancy_alpha, 1.5f);
  EXPECT_FLOAT_EQ(a.vorticity_epsilon, 2.0f);
  EXPECT_EQ(a.advection, AirAdvection::MacCormack);
  EXPECT_TRUE(a.open_face[1]);
  EXPECT_TRUE(a.open_face[3]);
  EXPECT_FALSE(a.open_face[0]);
  ASSERT_EQ(a.inflows.size(), 2u);
  EXPECT_EQ(a.inflows[0].shape, AirInflow::Shape::Disc);
  EXPECT_FLOAT_EQ(a.inflows[0].normal.x, 1.0f);  // normalised
  EXPECT_FLOAT_EQ(a.inflows[0].temperature, 308.15f);
  EXPECT_DOUBLE_EQ(a.inflows[0].vapor, 0.02);
  EXPECT_FLOAT_EQ(a.inflows[0].thickness, 0.7f / 12);  // one cell
  EXPECT_NEAR(a.inflows[1].vapor, a.ambient_vapor, 1e-12);  // defaults to the ambient air
  EXPECT_FLOAT_EQ(a.domain_max.x, 0.35f);  // the simulation domain
  EXPECT_FLOAT_EQ(a.projection_tolerance, 1e-6f);
  EXPECT_EQ(a.projection_max_iterations, 50);
}

TEST(air_Scene, NoAirSectionNoAirPhase) {
  std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  const Scene s = load_scene(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  EXPECT_FALSE(s.simulation.air.has_value());
  EXPECT_FALSE(make_simulation_setup(s).air.has_value());
}

TEST(air_Scene, CellsNotLargerThanTwoSupportRadiiAreRejected) {
  const std::string e = error_of({{"resolution", 15}}, "fine.json");
  SCOPED_TRACE(e);
  EXPECT_NE(e.find("fine.json: simulation.air.resolution: air cell size"), std::string::npos) << e;
  EXPECT_NE(e.find("two support radii"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 13 cells"), std::string::npos) << e;
}

TEST(air_Scene, BadValuesNameTheirKeys) {
  EXPECT_NE(error_of({{"resolution", 12}, {"relative_humidity", 0.5}, {"vapor_kg_m3", 0.01}}, "both.json")
                .find("simulation.air.vapor_kg_m3: give relative_humidity or vapor_kg_m3, not both"),
            std::string::npos);
  EXPECT_NE(error_of({{"resolution", 12}, {"relative_humidity", 1.5}}, "rh.json").find("simulation.air.relative_humidity: expected a number in [0, 1]"),
            std::string::npos);
  EXPECT_NE(error_of({{"resolution", 12}, {"boundary", {{"x_min", "wall"}}}}, "face.json")
                .find("simulation.air.boundary.x_min: expected \"closed\" or \"open\", found \"wall\""),
            std::string::npos);
  EXPECT_NE(error_of({{"resolution", 12}, {"inflows", {{{"shape", "box"}, {"min_m", {0, 0, 0}}, {"max_m", {0.1, 0.1, 0.1}},
                                                      {"velocity_m_s", {1, 0, 0}}}}}},
                     "closed.json")
                .find("simulation.air.inflows: blow air into a closed domain"),
            std::string::npos);
  EXPECT_NE(error_of({{"resolution", 12}, {"inflows", {{{"shape", "cone"}}}}}, "cone.json")
                .find("simulation.air.inflows[0].shape: expected \"box\" or \"disc\", found \"cone\""),
            std::string::npos);
  const std::string unknown = error_of({{"resolution", 12}, {"wind", 1}}, "unknown.json");
  EXPECT_NE(unknown.find("simulation.air.wind: unknown key"), std::string::npos) << unknown;
}

// The VDB holds the three grids at cell centres in world space: read back
// with OpenVDB itself, voxel (i, j, k) lands on cell (i, j, k)'s centre and
// holds its values.
TEST(air_Vdb, GridsLandInWorldSpaceWithTheCellsValues) {
  AirSnapshot s;
  s.grid.origin = Vec3{-0.35f, -0.05f, 0.1f};
  s.grid.dx = 0.05f;
  s.grid.nx = 4;
  s.grid.ny = 3;
  s.grid.nz = 2;
  const std::size_t n = s.grid.cell_count();
  s.kind.assign(n, 0);
  for (std::size_t c = 0; c < n; ++c) {
    s.vapor.push_back(0.001 * c);
    s.temperature.push_back(290.0f + c);
  }
  s.u.resize(s.grid.face_count(0));
  s.v.resize(s.grid.face_count(1));
  s.w.resize(s.grid.face_count(2));
  for (std::size_t f = 0; f < s.u.size(); ++f) s.u[f] = 0.1f * f;
  const fs::path file = fs::temp_directory_path() / ("dewpoint-air-io-test-" + std::to_string(::getpid())) / "air.0003.vdb";
  fs::create_directories(file.parent_path());
  write_air_frame(file, s, "test");

  openvdb::initialize();
  openvdb::io::File in(file.string());
  in.open();
  auto vapor = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("vapor_density"));
  auto temperature = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("temperature"));
  auto velocity = openvdb::gridPtrCast<openvdb::Vec3SGrid>(in.readGrid("velocity"));
  in.close();
  ASSERT_TRUE(vapor && temperature && velocity);
  EXPECT_EQ(vapor->activeVoxelCount(), n);
  const Vec3 c = s.grid.cell_center(2, 1, 1);
  const openvdb::Vec3d world = vapor->transform().indexToWorld(openvdb::Coord(2, 1, 1));
  EXPECT_NEAR(world.x(), c.x, 1e-6);
  EXPECT_NEAR(world.y(), c.y, 1e-6);
  EXPECT_NEAR(world.z(), c.z, 1e-6);
  const std::size_t cell = s.grid.cell(2, 1, 1);
  EXPECT_FLOAT_EQ(vapor->tree().getValue(openvdb::Coord(2, 1, 1)), static_cast<float>(s.vapor[cell]));
  EXPECT_FLOAT_EQ(temperature->tree().getValue(openvdb::Coord(2, 1, 1)), s.temperature[cell]);
  const openvdb::Vec3s v = velocity->tree().getValue(openvdb::Coord(2, 1, 1));
  EXPECT_FLOAT_EQ(v.x(), 0.5f * (s.u[s.grid.face(0, 2, 1, 1)] + s.u[s.grid.face(0, 3, 1, 1)]));
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

}  // namespace
}  // namespace dp::io
