// dewpoint-simulate's --log-level and its progress through a pipe (as on a
// render farm): at most one progress line per frame, none at error or warn,
// warnings from warn up, one line per step at debug. Counts are checked
// against the run's own manifest and timings.csv.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "frames.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

class LogLevelCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-log-level-cli-" + std::to_string(getpid()) + "-");
    fs::remove_all(work_);
    fs::create_directories(work_);
    std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
    nlohmann::json doc = nlohmann::json::parse(in);
    auto& sim = doc["simulation"];
    sim["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
    sim["duration_s"] = 0.1;
    sim["frame_rate_hz"] = 40;  // frames 0-4
    sim["liquid_blocks"][0]["min_m"] = {-0.025, 0.03, -0.025};
    sim["liquid_blocks"][0]["max_m"] = {0.025, 0.08, 0.025};
    std::ofstream(work_ / "shot.json") << doc.dump(2);
  }
  void TearDown() override { fs::remove_all(work_); }
  // stderr only, through a pipe: not a terminal.
  test::CommandResult simulate(const std::string& flags) {
    return test::run_command("{ " + std::string(DEWPOINT_SIMULATE) + " " + (work_ / "shot.json").string() + " -o " +
                             (work_ / "out").string() + " --threads 2 " + flags + " 2>&1 >/dev/null; }");
  }
  static int lines_starting(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    int n = 0;
    for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0 ? 1 : 0;
    return n;
  }
  std::int64_t timing_rows() const {
    std::ifstream csv(work_ / "out/stats/timings.csv");
    std::int64_t rows = -1;  // the header
    for (std::string line; std::getline(csv, line);) ++rows;
    return rows;
  }

  fs::path work_;
};

TEST_F(LogLevelCli, InfoThroughAPipeGivesOneProgressLinePerFrame) {
  const test::CommandResult r = simulate("--log-level info");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const io::FramesManifest m = io::read_manifest(work_ / "out/frames");
  ASSERT_EQ(m.frames.size(), 5u);
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "no carriage returns in a log";
  // One line per frame, "simulate NAME k/5 ...", then the closing "done" line.
  EXPECT_EQ(lines_starting(r.output, "simulate demo "), 5 + 1) << r.output;
  EXPECT_EQ(lines_starting(r.output, "simulate demo 5/5 "), 1) << r.output;
  EXPECT_NE(r.output.find("steps/s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ETA"), std::string::npos) << r.output;
  EXPECT_GT(timing_rows(), 5) << "more steps than frames, or the test shows nothing";
}

TEST_F(LogLevelCli, ErrorAndQuietSayNothingOnSuccess) {
  // Two frames are enough: at info they would give progress lines and the timing summary.
  for (const std::string flags : {"--log-level error", "--quiet"}) {
    const test::CommandResult r = simulate(flags + " --frames 0-1");
    EXPECT_EQ(r.exit_code, 0) << flags << ": " << r.output;
    EXPECT_EQ(r.output, "") << flags;
  }
}

TEST_F(LogLevelCli, WarnShowsWarningsButNoProgress) {
  // --resume into an empty OUT: a warning, then a run from the start.
  const test::CommandResult r = simulate("--log-level warn --resume --frames 0-1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: --resume: no usable checkpoint"), std::string::npos) << r.output;
  EXPECT_EQ(lines_starting(r.output, "simulate demo "), 0) << r.output;
  const test::CommandResult quiet = simulate("--quiet --resume --frames 0-1");
  EXPECT_EQ(quiet.output.find("warning"), std::string::npos) << quiet.output;
}

TEST_F(LogLevelCli, DebugGivesOneLinePerStep) {
  const test::CommandResult r = simulate("--log-level debug");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(lines_starting(r.output, "dewpoint-simulate: step "), timing_rows()) << r.output;
}

TEST_F(LogLevelCli, BadLevelAndQuietWithALevelAreRefused) {
  const test::CommandResult bad = simulate("--log-level chatty");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--log-level"), std::string::npos) << bad.output;
  const test::CommandResult both = simulate("--quiet --log-level debug");
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_FALSE(fs::exists(work_ / "out"));
}

}  // namespace
}  // namespace dp
