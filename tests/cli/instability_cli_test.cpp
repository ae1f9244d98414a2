// A scene made to blow up: dewpoint-simulate exits 3 with a message naming
// the step, the quantity and the particle (or air cell); what it wrote
// before is intact: every frame the manifest lists reads back, and the last
// checkpoint loads and resumes without a crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <openvdb/openvdb.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "checkpoint_folder.h"
#include "frames.h"
#include "ply.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

class InstabilityCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-instability-cli-" + std::to_string(getpid()) + "-");
    fs::remove_all(work_);
    fs::create_directories(work_);
    std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
    doc_ = nlohmann::json::parse(in);
    auto& sim = doc_["simulation"];
    sim["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
    sim["rigids"][0]["texture"] = {{"resolution", {16, 8}}};
    sim["air"] = {{"resolution", 12}};
    sim["duration_s"] = 0.2;
    sim["frame_rate_hz"] = 100;
    sim["liquid_blocks"][0]["min_m"] = {-0.025, 0.03, -0.025};
    sim["liquid_blocks"][0]["max_m"] = {0.025, 0.08, 0.025};
  }
  void TearDown() override { fs::remove_all(work_); }

  test::CommandResult simulate(const std::string& flags = "--quiet") {
    std::ofstream(work_ / "shot.json") << doc_.dump(2);
    return test::run_command(std::string(DEWPOINT_SIMULATE) + " " + (work_ / "shot.json").string() + " -o " +
                             (work_ / "out").string() + " --threads 2 --checkpoint-every 1 " + flags);
  }
  fs::path frames() const { return work_ / "out/frames"; }

  fs::path work_;
  nlohmann::json doc_;
};

void expect_particles_readable(const fs::path& file, std::size_t count) {
  const io::PlyData p = io::read_ply(file);
  EXPECT_EQ(p.vertex_count, count) << file;
  ASSERT_NE(p.find("y"), nullptr) << file;
  for (double y : p.find("y")->values) ASSERT_TRUE(std::isfinite(y)) << file;
}

void expect_surface_readable(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in) << file << ": " << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) << file << ": " << in->geterror();
}

void expect_air_readable(const fs::path& file) {
  openvdb::initialize();
  openvdb::io::File in(file.string());
  ASSERT_NO_THROW(in.open()) << file;
  for (const char* grid : {"vapor_density", "temperature", "velocity"}) EXPECT_TRUE(in.readGrid(grid)) << file << " " << grid;
  in.close();
}

TEST_F(InstabilityCli, SpeedBoundExceededExitsThreeAndLeavesReadableFramesAndCheckpoint) {
  // The falling block passes 0.8 m/s after about 0.07 s: frames 0-6 come first.
  doc_["simulation"]["max_speed_m_s"] = 0.8;
  const test::CommandResult r = simulate();
  ASSERT_EQ(r.exit_code, 3) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex("unstable at step [0-9]+: speed of liquid particle id [0-9]+ at \\(")))
      << r.output;
  EXPECT_NE(r.output.find("exceeds the bound 0.8 m/s"), std::string::npos) << r.output;

  const io::FramesManifest m = io::read_manifest(frames());
  ASSERT_GE(m.frames.size(), 3u) << "the blow-up came before any frame worth checking";
  for (const io::FrameEntry& f : m.frames) {
    expect_particles_readable(frames() / f.particles_file, f.liquid_particles);
    expect_surface_readable(frames() / f.surface_files.at("tray"));
    expect_air_readable(frames() / f.air_file);
  }
  const io::NewestCheckpoint newest = io::find_newest_checkpoint(work_ / "out/checkpoints");
  ASSERT_TRUE(newest.checkpoint) << "no loadable checkpoint";
  EXPECT_TRUE(newest.skipped.empty());
  EXPECT_EQ(newest.checkpoint->frame, m.frames.back().index) << "a checkpoint follows every frame";

  // Resuming runs into the same blow-up, and says so the same way.
  const test::CommandResult resumed = simulate("--log-level info --resume");
  EXPECT_EQ(resumed.exit_code, 3) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming after frame " + std::to_string(newest.checkpoint->frame)), std::string::npos)
      << resumed.output;
  EXPECT_NE(resumed.output.find("speed of liquid particle id"), std::string::npos) << resumed.output;
  EXPECT_EQ(io::read_manifest(frames()).frames.size(), m.frames.size());
}

TEST_F(InstabilityCli, NonFiniteAirExitsThreeNamingTheAirCellOrFace) {
  // A hot tray held at 500 °C under an absurd buoyancy coefficient: the air's
  // velocity overflows to infinity, then NaN, within a few steps.
  doc_["simulation"]["air"]["buoyancy_beta"] = 1e38;
  doc_["simulation"]["rigids"][0]["temperature_c"] = 500;
  doc_["simulation"]["rigids"][0]["hold_temperature"] = true;
  doc_["simulation"]["duration_s"] = 0.1;
  const test::CommandResult r = simulate();
  ASSERT_EQ(r.exit_code, 3) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex("unstable at step [0-9]+: air [a-z ]+ is not finite in air (cell|face) [0-9]+")))
      << r.output;
  const io::FramesManifest m = io::read_manifest(frames());
  ASSERT_GE(m.frames.size(), 1u);
  for (const io::FrameEntry& f : m.frames) {
    expect_particles_readable(frames() / f.particles_file, f.liquid_particles);
    expect_air_readable(frames() / f.air_file);
  }
}

TEST_F(InstabilityCli, AbsurdGravityExitsThreeNamingStepAndQuantity) {
  doc_["simulation"]["gravity_m_s2"] = {0, -1e9, 0};
  const test::CommandResult r = simulate();
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex("unstable at step [0-9]+: [a-z ]+"))) << r.output;
  EXPECT_FALSE(fs::exists(frames() / "manifest.json") && io::read_manifest(frames()).frames.size() > 1);
}

}  // namespace
}  // namespace dp
