// dewpoint-simulate with an air phase: air.%04d.vdb per frame, listed in the
// manifest with a vapor ledger that balances; a scene whose air cells are too
// small is refused before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "frames.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

class air_SimulateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-air-cli-");
    fs::remove_all(work_);
    fs::create_directories(work_);
    std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
    doc_ = nlohmann::json::parse(in);
    doc_["simulation"]["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
    doc_["simulation"]["duration_s"] = 0.1;
    doc_["simulation"]["frame_rate_hz"] = 20;
    doc_["simulation"]["liquid_blocks"][0]["min_m"] = {-0.0375, 0.03, -0.0375};
    doc_["simulation"]["liquid_blocks"][0]["max_m"] = {0.0375, 0.105, 0.0375};
    doc_["simulation"]["air"] = {
        {"resolution", 12},
        {"boundary", {{"x_max", "open"}, {"y_max", "open"}}},
        {"inflows",
         {{{"shape", "disc"}, {"center_m", {-0.3, 0.2, 0}}, {"normal", {1, 0, 0}}, {"radius_m", 0.1},
           {"velocity_m_s", {1, 0, 0}}, {"temperature_c", 35}, {"relative_humidity", 0.9}}}}};
  }
  test::CommandResult simulate() {
    const fs::path scene = work_ / "shot.json";
    std::ofstream(scene) << doc_.dump(2);
    return test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " -o " + (work_ / "out").string() +
                             " --threads 1 --quiet");
  }
  fs::path work_;
  nlohmann::json doc_;
};

TEST_F(air_SimulateCli, WritesAirFramesAndABalancedLedger) {
  const test::CommandResult r = simulate();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const io::FramesManifest m = io::read_manifest(work_ / "out/frames");
  ASSERT_EQ(m.frames.size(), 3u);
  for (const io::FrameEntry& f : m.frames) {
    EXPECT_EQ(f.air_file, io::frame_file_name("air", f.index, "vdb"));
    EXPECT_TRUE(fs::exists(work_ / "out/frames" / f.air_file)) << f.air_file;
    const nlohmann::json& l = f.air_vapor;
    const double mass = l.at("mass_kg"), expected = l.at("initial_kg").get<double>() + l.at("inflow_gain_kg").get<double>() +
                                                    l.at("open_in_kg").get<double>() - l.at("open_out_kg").get<double>() +
                                                    l.at("exchanged_kg").get<double>();
    EXPECT_NEAR(mass, expected, 1e-9 * mass);
  }
  EXPECT_GT(m.frames.back().air_vapor.at("inflow_gain_kg").get<double>(), 0.0);
}

TEST_F(air_SimulateCli, TooFineAirGridIsRefusedBeforeWriting) {
  doc_["simulation"]["air"]["resolution"] = 20;
  const test::CommandResult r = simulate();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("simulation.air.resolution: air cell size"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work_ / "out"));
}

}  // namespace
}  // namespace dp
