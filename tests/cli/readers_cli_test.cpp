// dewpoint-simulate's frames as tools nobody here wrote read them: the
// particle PLY by assimp, the air VDB by OpenVDB's vdb_print, the surface
// EXR by OpenImageIO's oiiotool. Each must open the file and list what
// docs/file-formats.md promises.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "frames.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

bool tool_present(const std::string& name) { return test::run_command("command -v " + name + " >/dev/null").exit_code == 0; }

// One short run, read by all three tools: a textured tray, air, two frames.
// One test, so that ctest's process per test runs the simulation once.
class ReadersCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = fs::temp_directory_path() / ("dewpoint-readers-cli-" + std::to_string(getpid()));
    fs::remove_all(work_);
    fs::create_directories(work_);
    std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
    nlohmann::json doc = nlohmann::json::parse(in);
    auto& sim = doc["simulation"];
    sim["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
    sim["rigids"][0]["texture"] = {{"resolution", {16, 8}}, {"initial_mass_kg_m2", 0.01}};
    sim["air"] = {{"resolution", 12}};
    sim["duration_s"] = 0.05;
    sim["frame_rate_hz"] = 20;
    sim["liquid_blocks"][0]["min_m"] = {-0.025, 0.03, -0.025};
    sim["liquid_blocks"][0]["max_m"] = {0.025, 0.08, 0.025};
    std::ofstream(work_ / "shot.json") << doc.dump(2);
    const test::CommandResult run = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + (work_ / "shot.json").string() +
                                                      " -o " + (work_ / "out").string() + " --threads 2 --quiet");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const io::FramesManifest m = io::read_manifest(work_ / "out/frames");
    ASSERT_EQ(m.frames.size(), 2u);
    frame_ = m.frames.back();
  }
  void TearDown() override { fs::remove_all(work_); }
  std::string frame_file(const std::string& file) const { return (work_ / "out/frames" / file).string(); }

  fs::path work_;
  io::FrameEntry frame_;
};

// assimp's raw import (-r): its default post-processing rejects a mesh
// without faces, which a particle cloud is.
void expect_assimp_reads_particles(const std::string& file, std::size_t particles) {
  const test::CommandResult r = test::run_command("assimp info " + file + " -r");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex("Vertices:\\s+([0-9]+)"))) << r.output;
  EXPECT_EQ(std::stoul(m[1].str()), particles) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex("Primitive Types:\\s+points"))) << r.output;
}

void expect_vdb_print_lists_air_grids(const std::string& file) {
  const test::CommandResult r = test::run_command("vdb_print -l " + file);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* grid : {"vapor_density", "temperature", "velocity"})
    EXPECT_TRUE(std::regex_search(r.output, std::regex(std::string("(^|\\n)Name: ") + grid + "\\b|(^|\\n)" + grid + "\\s")))
        << grid << " not listed in: " << r.output;
}

void expect_oiiotool_lists_surface_channels(const std::string& file) {
  const test::CommandResult r = test::run_command("oiiotool --info -v " + file);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(":\\s+16 x\\s+8, 4 channel"))) << "the texture's resolution: " << r.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex("channel list: ([^\\n]*)"))) << r.output;
  const std::string channels = m[1].str();
  for (const char* c : {"mass", "max_mass", "temperature", "wetting"})
    EXPECT_TRUE(std::regex_search(channels, std::regex(std::string("(^|[ ,])") + c + "([ ,(]|$)"))) << c << " not in: " << channels;
}

TEST_F(ReadersCli, ToolsNotOursReadEveryKindOfFrameFile) {
  std::string absent;
  if (tool_present("assimp")) expect_assimp_reads_particles(frame_file(frame_.particles_file), frame_.liquid_particles);
  else absent += " assimp (Debian assimp-utils)";
  if (tool_present("vdb_print")) expect_vdb_print_lists_air_grids(frame_file(frame_.air_file));
  else absent += " vdb_print (Debian libopenvdb-tools)";
  if (tool_present("oiiotool")) expect_oiiotool_lists_surface_channels(frame_file(frame_.surface_files.at("tray")));
  else absent += " oiiotool (Debian openimageio-tools)";
  if (!absent.empty()) GTEST_SKIP() << "not installed:" << absent << "; pipelines/install-deps.sh installs them";
}

}  // namespace
}  // namespace dp
