// dewpoint-simulate killed mid-run (SIGKILL, no chance to clean up) and
// resumed with --resume writes the same frames, byte for byte, as a run
// that was never interrupted: the checkpoint holds all state that later
// steps read. The scene has air, a textured rigid holding water and the
// coupling between them, so every part of the state takes part.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "checkpoint_folder.h"
#include "frames.h"
#include "run_command.h"

extern char** environ;

namespace fs = std::filesystem;

namespace dp {
namespace {

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// OpenVDB stamps every file it writes with a fresh random UUID, 36
// characters after the 21-byte header start (magic, file version, library
// version, offsets flag); every other byte must agree.
std::string without_vdb_uuid(std::string bytes) {
  constexpr std::size_t kUuidAt = 8 + 4 + 4 + 4 + 1, kUuidLength = 36;
  if (bytes.size() >= kUuidAt + kUuidLength) bytes.replace(kUuidAt, kUuidLength, kUuidLength, '-');
  return bytes;
}

class ResumeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-resume-cli-");
    fs::remove_all(work_);
    fs::create_directories(work_);
    std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
    doc_ = nlohmann::json::parse(in);
    auto& sim = doc_["simulation"];
    sim["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
    sim["rigids"][0]["temperature_c"] = 45;  // a warm tray: its water evaporates
    sim["rigids"][0]["texture"] = {{"resolution", {32, 16}}, {"initial_mass_kg_m2", 0.02}};
    sim["duration_s"] = 0.2;
    sim["frame_rate_hz"] = 40;
    sim["liquid_blocks"][0]["min_m"] = {-0.0375, 0.03, -0.0375};
    sim["liquid_blocks"][0]["max_m"] = {0.0375, 0.08, 0.0375};
    sim["air"] = {{"resolution", 12},
                  {"boundary", {{"x_max", "open"}, {"y_max", "open"}}},
                  {"inflows",
                   {{{"shape", "disc"}, {"center_m", {-0.3, 0.2, 0}}, {"normal", {1, 0, 0}}, {"radius_m", 0.1},
                     {"velocity_m_s", {1, 0, 0}}, {"temperature_c", 35}, {"relative_humidity", 0.9}}}}};
    scene_ = work_ / "shot.json";
    std::ofstream(scene_) << doc_.dump(2);
  }

  std::vector<std::string> arguments(const fs::path& out, const std::vector<std::string>& extra) const {
    // info: the test reads the "resuming after frame" and "starting from the beginning" lines.
    std::vector<std::string> a{DEWPOINT_SIMULATE, scene_.string(), "-o", out.string(), "--threads", "2", "--log-level", "info",
                               "--checkpoint-every", "1"};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }

  test::CommandResult run(const fs::path& out, const std::vector<std::string>& extra = {}) const {
    std::string command;
    for (const std::string& a : arguments(out, extra)) command += "'" + a + "' ";
    return test::run_command(command);
  }

  // Starts the simulator, waits until its first checkpoint exists, kills it
  // with SIGKILL; returns whether it was still running when killed.
  bool run_and_kill_after_first_checkpoint(const fs::path& out) const {
    std::vector<std::string> args = arguments(out, {});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline && !io::find_newest_checkpoint(out / "checkpoints").checkpoint)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
  }

  friend void expect_killed_and_resumed_run_writes_the_same_frames(ResumeCli& t);
  fs::path work_, scene_;
  nlohmann::json doc_;
};

// The uninterrupted run into a, the killed and resumed one into b, and
// their frames compared.
void expect_killed_and_resumed_run_writes_the_same_frames(ResumeCli& t);

TEST_F(ResumeCli, KilledAndResumedRunWritesTheSameFramesBitForBit) { expect_killed_and_resumed_run_writes_the_same_frames(*this); }

// Warm-started PCISPH reads the last step's pressures, which the checkpoint
// must therefore carry in the order the next step expects.
TEST_F(ResumeCli, KilledAndResumedWarmStartedRunWritesTheSameFramesBitForBit) {
  doc_["simulation"]["pressure_solver"] = {{"warm_start", true}};
  std::ofstream(scene_) << doc_.dump(2);
  expect_killed_and_resumed_run_writes_the_same_frames(*this);
}

void expect_killed_and_resumed_run_writes_the_same_frames(ResumeCli& t) {
  const fs::path a = t.work_ / "a", b = t.work_ / "b";
  auto run = [&](const fs::path& out, const std::vector<std::string>& extra = {}) { return t.run(out, extra); };
  auto run_and_kill_after_first_checkpoint = [&](const fs::path& out) { return t.run_and_kill_after_first_checkpoint(out); };
  const test::CommandResult whole = run(a);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;

  ASSERT_TRUE(run_and_kill_after_first_checkpoint(b)) << "the run ended before it could be killed";
  const io::FramesManifest partial = io::read_manifest(b / "frames");
  const io::FramesManifest complete = io::read_manifest(a / "frames");
  ASSERT_LT(partial.frames.size(), complete.frames.size()) << "killed after the last frame: nothing left to resume";
  const test::CommandResult resumed = run(b, {"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming after frame"), std::string::npos) << resumed.output;

  const io::FramesManifest ma = io::read_manifest(a / "frames"), mb = io::read_manifest(b / "frames");
  ASSERT_EQ(ma.frames.size(), mb.frames.size());
  std::set<std::string> files;
  for (std::size_t i = 0; i < ma.frames.size(); ++i) {
    const io::FrameEntry &fa = ma.frames[i], &fb = mb.frames[i];
    EXPECT_EQ(fa.index, fb.index);
    EXPECT_EQ(fa.step, fb.step) << "frame " << fa.index;
    EXPECT_EQ(fa.water, fb.water) << "frame " << fa.index;
    EXPECT_EQ(fa.air_vapor, fb.air_vapor) << "frame " << fa.index;
    files.insert(fa.particles_file);
    files.insert(fa.air_file);
    for (const auto& [rigid, name] : fa.surface_files) files.insert(name);
  }
  EXPECT_EQ(files.size(), 3 * ma.frames.size()) << "particles, air and surface files per frame";
  for (const std::string& name : files) {
    std::string fa = bytes_of(a / "frames" / name), fb = bytes_of(b / "frames" / name);
    ASSERT_FALSE(fa.empty()) << name;
    if (fs::path(name).extension() == ".vdb") {
      fa = without_vdb_uuid(fa);
      fb = without_vdb_uuid(fb);
    }
    EXPECT_TRUE(fa == fb) << name << " differs between the uninterrupted and the resumed run";
  }
  // Water really moved between the stores, so the coupling's state mattered.
  const nlohmann::json& last = ma.frames.back().water;
  EXPECT_GT(last.at("texels_to_air_kg").get<double>() + last.at("liquid_to_air_kg").get<double>(), 0.0);

  // The timing table continues: one row per step, steps 1..N once each.
  std::ifstream csv(b / "stats/timings.csv");
  std::string line;
  std::getline(csv, line);
  std::int64_t expected_step = 1;
  while (std::getline(csv, line)) EXPECT_EQ(std::stoll(line.substr(0, line.find(','))), expected_step++) << line;
  EXPECT_EQ(expected_step - 1, mb.frames.back().step);
}

TEST_F(ResumeCli, ResumeWithoutCheckpointStartsFromTheBeginning) {
  const test::CommandResult r = run(work_ / "out", {"--resume", "--frames", "0-2"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("starting from the beginning"), std::string::npos) << r.output;
  EXPECT_EQ(io::read_manifest(work_ / "out/frames").frames.size(), 3u);
}

// A second run into the same folder without --resume, shorter than the
// first: a later --resume must continue it, not the first run, whose
// later checkpoints would otherwise outrank its own.
TEST_F(ResumeCli, RunStartedOverReplacesTheEarlierRunsCheckpoints) {
  const fs::path out = work_ / "out";
  const auto checkpoints_left = [&] {
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(out / "checkpoints")) left.push_back(entry.path().filename().string());
    return left;
  };
  const test::CommandResult first = run(out);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const io::NewestCheckpoint newest = io::find_newest_checkpoint(out / "checkpoints");
  ASSERT_TRUE(newest.checkpoint.has_value());
  ASSERT_GT(newest.checkpoint->frame, 1);

  // Frames 0-2 checkpoint after frame 1 only: that is all that is left.
  const test::CommandResult again = run(out, {"--frames", "0-2"});
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(checkpoints_left(), std::vector<std::string>{io::checkpoint_file(out / "checkpoints", 1).filename().string()});
  const test::CommandResult resumed = run(out, {"--resume", "--frames", "0-2"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming after frame 1 "), std::string::npos) << resumed.output;

  // Frames 0-1 write no checkpoint at all: none is left to resume from.
  const test::CommandResult shortest = run(out, {"--frames", "0-1"});
  ASSERT_EQ(shortest.exit_code, 0) << shortest.output;
  EXPECT_TRUE(checkpoints_left().empty());
}

TEST_F(ResumeCli, ChangedSceneIsRefused) {
  const fs::path out = work_ / "out";
  ASSERT_TRUE(run_and_kill_after_first_checkpoint(out));
  const std::string manifest_before = bytes_of(out / "frames/manifest.json");
  doc_["simulation"]["liquid"]["temperature_c"] = 30;
  std::ofstream(scene_) << doc_.dump(2);
  const test::CommandResult r = run(out, {"--resume"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("shot.json has changed"), std::string::npos) << r.output;
  EXPECT_EQ(bytes_of(out / "frames/manifest.json"), manifest_before) << "a refused resume must not touch the output";
}

}  // namespace
}  // namespace dp
