// Bad input to dewpoint-simulate, as users meet it: exit code 2, a message
// naming the file, the key and what was expected versus found, and OUT left
// as it was (not created; or, holding an earlier run, byte for byte the same).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

const fs::path kSource = DEWPOINT_SOURCE_DIR;

std::map<fs::path, std::string> files_under(const fs::path& dir) {
  std::map<fs::path, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      std::ifstream in(e.path(), std::ios::binary);
      files[fs::relative(e.path(), dir)] = std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
  return files;
}

class ValidationCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-validation-cli-" + std::to_string(getpid()) + "-");
    fs::remove_all(work_);
    fs::create_directories(work_ / "meshes");
    fs::copy_file(kSource / "assets/meshes/tray.obj", work_ / "meshes/tray.obj");
    std::ifstream in(kSource / "assets/scenes/demo.json");
    doc_ = nlohmann::json::parse(in);
    auto& sim = doc_["simulation"];
    sim["rigids"][0]["mesh"] = "meshes/tray.obj";
    sim["duration_s"] = 0.05;
    sim["frame_rate_hz"] = 20;
    sim["liquid_blocks"][0]["min_m"] = {-0.025, 0.03, -0.025};
    sim["liquid_blocks"][0]["max_m"] = {0.025, 0.08, 0.025};
  }
  void TearDown() override { fs::remove_all(work_); }

  test::CommandResult simulate(const nlohmann::json& doc) {
    std::ofstream(work_ / "shot.json") << doc.dump(2);
    return test::run_command(std::string(DEWPOINT_SIMULATE) + " " + (work_ / "shot.json").string() + " -o " +
                             (work_ / "out").string() + " --threads 1 --quiet");
  }
  // Exit 2, every fragment in the message, and no OUT.
  void expect_refused(const nlohmann::json& doc, const std::vector<std::string>& fragments) {
    const test::CommandResult r = simulate(doc);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const std::string& f : fragments) EXPECT_NE(r.output.find(f), std::string::npos) << "missing '" << f << "' in: " << r.output;
    EXPECT_FALSE(fs::exists(work_ / "out")) << "OUT was created for bad input";
  }
  fs::path write_mesh(const std::string& name, const std::string& obj) {
    std::ofstream(work_ / "meshes" / name) << obj;
    return work_ / "meshes" / name;
  }

  fs::path work_;
  nlohmann::json doc_;
};

TEST_F(ValidationCli, MeshThatIsAFolderIsRefused) {
  fs::create_directories(work_ / "meshes/folder.obj");
  doc_["simulation"]["rigids"][0]["mesh"] = "meshes/folder.obj";
  expect_refused(doc_, {"shot.json", "simulation.rigids[0].mesh", "folder.obj", "is a directory"});
}

TEST_F(ValidationCli, MeshOfGarbageBytesIsRefused) {
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 7919 + 13) % 256);
  std::ofstream(work_ / "meshes/garbage.ply", std::ios::binary) << garbage;
  doc_["simulation"]["rigids"][0]["mesh"] = "meshes/garbage.ply";
  expect_refused(doc_, {"shot.json", "simulation.rigids[0].mesh", "garbage.ply"});
}

TEST_F(ValidationCli, NonManifoldMeshIsRefused) {
  // Three triangles hinged on the edge (0,0,0)-(0.1,0,0): a book of three pages.
  write_mesh("book.obj",
             "v 0 0 0\nv 0.1 0 0\nv 0.05 0.1 0\nv 0.05 0 0.1\nv 0.05 -0.05 -0.05\n"
             "f 1 2 3\nf 1 2 4\nf 1 2 5\n");
  doc_["simulation"]["rigids"][0]["mesh"] = "meshes/book.obj";
  expect_refused(doc_, {"shot.json", "simulation.rigids[0].mesh", "book.obj", "not manifold", "shared by 3 triangles"});
}

TEST_F(ValidationCli, ZeroAreaMeshIsRefused) {
  // Every triangle's corners lie on one line.
  write_mesh("flat.obj", "v 0 0 0\nv 0.1 0 0\nv 0.2 0 0\nv 0.3 0 0\nf 1 2 3\nf 2 3 4\n");
  doc_["simulation"]["rigids"][0]["mesh"] = "meshes/flat.obj";
  expect_refused(doc_, {"shot.json", "simulation.rigids[0].mesh", "flat.obj", "expected a mesh with a positive surface area",
                        "found 0"});
}

TEST_F(ValidationCli, AirCellsNotLargerThanTwoSupportRadiiAreRefused) {
  doc_["simulation"]["air"] = {{"resolution", 40}};
  expect_refused(doc_, {"shot.json", "simulation.air.resolution", "air cell size"});
}

TEST_F(ValidationCli, RigidMeshOutsideTheDomainIsRefused) {
  doc_["simulation"]["domain"]["max_m"] = {0.35, 0.5, 0.25};  // the tray reaches z = 0.3
  expect_refused(doc_, {"shot.json", "simulation.rigids[0].mesh", "lies outside the simulation domain", "0.3"});
}

TEST_F(ValidationCli, LiquidBlockOutsideTheDomainIsRefused) {
  doc_["simulation"]["liquid_blocks"][0]["max_m"] = {0.025, 0.6, 0.025};
  expect_refused(doc_, {"shot.json", "simulation.liquid_blocks[0].max_m", "outside the simulation domain",
                        "found (0.025000, 0.600000, 0.025000)"});
}

TEST_F(ValidationCli, LiquidSphereReachingOutOfTheDomainIsRefused) {
  doc_["simulation"]["liquid_blocks"][0] = {{"shape", "sphere"}, {"center_m", {0, 0.45, 0}}, {"radius_m", 0.1}};
  expect_refused(doc_, {"shot.json", "simulation.liquid_blocks[0].radius_m", "highest corner", "outside the simulation domain",
                        "found (0.100000, 0.550000, 0.100000)"});
}

TEST_F(ValidationCli, InflowOutsideTheAirDomainIsRefused) {
  doc_["simulation"]["air"] = {
      {"resolution", 12},
      {"boundary", {{"y_max", "open"}}},
      {"inflows", {{{"shape", "disc"}, {"center_m", {0.9, 0.2, 0}}, {"normal", {1, 0, 0}}, {"radius_m", 0.1}}}}};
  expect_refused(doc_, {"shot.json", "simulation.air.inflows[0].center_m", "outside the air domain", "found (0.900000"});
  doc_["simulation"]["air"]["inflows"][0] = {{"shape", "box"}, {"min_m", {1, 0, 0}}, {"max_m", {1.1, 0.1, 0.1}}};
  expect_refused(doc_, {"shot.json", "simulation.air.inflows[0].min_m", "lies outside the air domain"});
}

TEST_F(ValidationCli, TemperatureBelowAbsoluteZeroIsRefused) {
  doc_["simulation"]["liquid"]["temperature_c"] = -300;
  expect_refused(doc_, {"shot.json", "simulation.liquid.temperature_c", "expected at least -273.15 °C", "found -300"});
  doc_["simulation"]["liquid"]["temperature_c"] = 20;
  doc_["simulation"]["rigids"][0]["temperature_c"] = -273.5;
  expect_refused(doc_, {"shot.json", "simulation.rigids[0].temperature_c", "found -273.5"});
  doc_["simulation"]["rigids"][0]["temperature_c"] = 20;
  doc_["simulation"]["air"] = {{"resolution", 12}, {"temperature_c", -1000}};
  expect_refused(doc_, {"shot.json", "simulation.air.temperature_c", "found -1000"});
}

TEST_F(ValidationCli, TemperatureInKelvinIsAWrongUnit) {
  // The format takes Celsius only; a kelvin key, negative or not, names the one to use.
  doc_["simulation"]["liquid"].erase("temperature_c");
  doc_["simulation"]["liquid"]["temperature_k"] = -5;
  expect_refused(doc_, {"shot.json", "simulation.liquid.temperature_k", "wrong unit", "expected simulation.liquid.temperature_c",
                        "found temperature_k = -5"});
}

TEST_F(ValidationCli, LengthInMillimetresIsAWrongUnit) {
  doc_["simulation"]["particle_spacing_mm"] = 12.5;
  expect_refused(doc_, {"shot.json", "simulation.particle_spacing_mm", "wrong unit", "expected simulation.particle_spacing_m",
                        "found particle_spacing_mm = 12.5"});
}

TEST_F(ValidationCli, AnEarlierRunInOutIsLeftByteForByte) {
  const test::CommandResult first = simulate(doc_);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto before = files_under(work_ / "out");
  ASSERT_FALSE(before.empty());
  nlohmann::json bad = doc_;
  bad["simulation"]["liquid"]["temperature_c"] = -300;
  EXPECT_EQ(simulate(bad).exit_code, 2);
  bad = doc_;
  fs::create_directories(work_ / "meshes/folder.obj");
  bad["simulation"]["rigids"][0]["mesh"] = "meshes/folder.obj";
  EXPECT_EQ(simulate(bad).exit_code, 2);
  bad = doc_;
  bad["simulation"]["liquid_blocks"][0]["max_m"] = {0.025, 0.6, 0.025};
  EXPECT_EQ(simulate(bad).exit_code, 2);
  EXPECT_EQ(files_under(work_ / "out"), before);
}

}  // namespace
}  // namespace dp
