// dewpoint-simulate as users run it: conventions, bad input, frames.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "frames.h"
#include "ply.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

const std::string kSimulate = DEWPOINT_SIMULATE;
const fs::path kSource = DEWPOINT_SOURCE_DIR;

class SimulateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-simulate-cli-");
    fs::remove_all(work_);
    fs::create_directories(work_ / "scenes");
    fs::create_directories(work_ / "meshes");
    fs::copy_file(kSource / "assets/meshes/tray.obj", work_ / "meshes/tray.obj");
    std::ifstream in(kSource / "assets/scenes/demo.json");
    doc_ = nlohmann::json::parse(in);
    // A short, small run: a 6x6x6 block, a tenth of a second.
    doc_["simulation"]["duration_s"] = 0.1;
    doc_["simulation"]["frame_rate_hz"] = 20;
    doc_["simulation"]["liquid_blocks"][0]["min_m"] = {-0.0375, 0.03, -0.0375};
    doc_["simulation"]["liquid_blocks"][0]["max_m"] = {0.0375, 0.105, 0.0375};
  }
  fs::path write_scene() {
    fs::path f = work_ / "scenes/shot.json";
    std::ofstream(f) << doc_.dump(2);
    return f;
  }
  test::CommandResult simulate(const std::string& args) {
    return test::run_command(kSimulate + " " + args);
  }
  fs::path work_;
  nlohmann::json doc_;
};

TEST_F(SimulateCli, HelpAndVersion) {
  auto help = simulate("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--device"), std::string::npos);
  auto version = simulate("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("dewpoint-simulate 0."), std::string::npos);
}

TEST_F(SimulateCli, WritesFramesAndManifest) {
  // The tray carries surface textures (docs/file-formats.md, rigid surfaces).
  doc_["simulation"]["rigids"][0]["texture"] = {{"resolution", {64, 32}}};
  fs::path scene = write_scene();
  auto r = simulate(scene.string() + " -o " + (work_ / "out").string() + " --quiet --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  io::FramesManifest m = io::read_manifest(work_ / "out/frames");
  ASSERT_EQ(m.frames.size(), 3u);  // t = 0, 0.05, 0.1
  EXPECT_NEAR(m.frames[2].time_s, 0.1, 1e-6);
  EXPECT_EQ(m.scene_file, fs::absolute(scene).lexically_normal());
  io::PlyData p = io::read_ply(work_ / "out/frames" / m.frames[2].particles_file);
  EXPECT_EQ(p.vertex_count, 216u);
  for (const char* name : {"x", "y", "z", "vx", "vy", "vz", "weight", "radius", "temperature", "density", "pressure", "surface_area", "id"})
    EXPECT_NE(p.find(name), nullptr) << name;
  // Falling liquid: after 0.1 s every particle has moved down.
  io::PlyData p0 = io::read_ply(work_ / "out/frames" / m.frames[0].particles_file);
  double mean0 = 0, mean2 = 0;
  for (double y : p0.find("y")->values) mean0 += y / 216;
  for (double y : p.find("y")->values) mean2 += y / 216;
  EXPECT_LT(mean2, mean0);
  EXPECT_TRUE(fs::exists(work_ / "out/frames/rigid_particles.ply"));
  ASSERT_EQ(m.rigids.size(), 1u);
  EXPECT_EQ(m.rigids[0].name, "tray");
  EXPECT_EQ(m.rigids[0].mesh_file, "rigid_tray.ply");
  EXPECT_EQ(m.rigids[0].texture_resolution, (std::array<int, 2>{64, 32}));
  io::PlyData atlas = io::read_ply(work_ / "out/frames/rigid_tray.ply");
  EXPECT_NE(atlas.find("s"), nullptr);
  EXPECT_FALSE(atlas.faces.empty());
  for (const auto& f : m.frames) EXPECT_TRUE(fs::exists(work_ / "out/frames" / f.surface_files.at("tray")));
  EXPECT_EQ(m.frames[2].surface_files.at("tray"), "surface_tray.0002.exr");
}

TEST_F(SimulateCli, WritesOneTimingRowPerStepAndTheirSummary) {
  fs::path scene = write_scene();
  auto r = simulate(scene.string() + " -o " + (work_ / "out").string() + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  io::FramesManifest m = io::read_manifest(work_ / "out/frames");
  std::ifstream csv(work_ / "out/stats/timings.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("step,time_s,dt_ms,ptcl_ms,grid_ms,neigh_ms,heat_ms,eva_ms", 0), 0u) << header;
  std::int64_t rows = 0;
  double sum_dt_ms = 0, max_ptcl = 0;
  while (std::getline(csv, line)) {
    ++rows;
    std::vector<double> v;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 11u) << line;
    EXPECT_EQ(v[0], static_cast<double>(rows)) << "steps numbered from 1";
    sum_dt_ms += v[2];
    max_ptcl = std::max(max_ptcl, v[3]);
  }
  // One row per step, and the steps' dtau add up to the last frame's time.
  EXPECT_EQ(rows, m.frames.back().step);
  EXPECT_NEAR(sum_dt_ms * 1e-3, m.frames.back().time_s, 1e-6);
  std::ifstream in(work_ / "out/stats/timings_summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["steps"].get<std::int64_t>(), rows);
  EXPECT_NEAR(summary["columns"]["Ptcl"]["max"].get<double>(), max_ptcl, 1e-5 * max_ptcl);  // the CSV keeps 6 digits
  EXPECT_NE(r.output.find("Neigh"), std::string::npos) << "the summary table is printed";
}

TEST_F(SimulateCli, FrameRangeWritesOnlyThoseFrames) {
  fs::path scene = write_scene();
  auto r = simulate(scene.string() + " -o " + (work_ / "out").string() + " --quiet --frames 1-2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(work_ / "out/frames/particles.0000.ply"));
  EXPECT_TRUE(fs::exists(work_ / "out/frames/particles.0001.ply"));
  EXPECT_TRUE(fs::exists(work_ / "out/frames/particles.0002.ply"));
}

void expect_rejected(const test::CommandResult& r, const fs::path& out, const std::vector<std::string>& fragments) {
  EXPECT_NE(r.exit_code, 0) << r.output;
  for (const auto& f : fragments) EXPECT_NE(r.output.find(f), std::string::npos) << "missing '" << f << "' in: " << r.output;
  EXPECT_FALSE(fs::exists(out)) << "output was written for bad input";
}

TEST_F(SimulateCli, UnknownKeyIsRejectedBeforeAnyOutput) {
  doc_["simulation"]["liquid"]["colour"] = "blue";
  fs::path scene = write_scene();
  expect_rejected(simulate(scene.string() + " -o " + (work_ / "out").string()), work_ / "out",
                  {"shot.json", "simulation.liquid.colour", "unknown key"});
}

TEST_F(SimulateCli, ZeroTextureResolutionIsRejectedBeforeAnyOutput) {
  doc_["simulation"]["rigids"][0]["texture"] = {{"resolution", {0, 0}}};
  fs::path scene = write_scene();
  expect_rejected(simulate(scene.string() + " -o " + (work_ / "out").string()), work_ / "out",
                  {"shot.json", "simulation.rigids[0].texture.resolution", "found [0, 0]"});
}

TEST_F(SimulateCli, WrongTypeIsRejectedBeforeAnyOutput) {
  doc_["render"]["spp"] = 1.5;
  fs::path scene = write_scene();
  expect_rejected(simulate(scene.string() + " -o " + (work_ / "out").string()), work_ / "out",
                  {"shot.json", "render.spp", "expected an integer, found a number"});
}

TEST_F(SimulateCli, MissingMeshIsRejectedBeforeAnyOutput) {
  doc_["simulation"]["rigids"][0]["mesh"] = "../meshes/gone.obj";
  fs::path scene = write_scene();
  expect_rejected(simulate(scene.string() + " -o " + (work_ / "out").string()), work_ / "out",
                  {"shot.json", "simulation.rigids[0].mesh", "gone.obj"});
}

TEST_F(SimulateCli, CudaWithoutGpuIsAClearError) {
  std::string why;
  if (cuda_device_count(&why) > 0) GTEST_SKIP() << "a GPU is present";
  fs::path scene = write_scene();
  auto r = simulate(scene.string() + " -o " + (work_ / "out").string() + " --device cuda");
  expect_rejected(r, work_ / "out", {"--device cuda"});
}

TEST_F(SimulateCli, MissingSceneFile) {
  auto r = simulate((work_ / "nothing.json").string() + " -o " + (work_ / "out").string());
  expect_rejected(r, work_ / "out", {"nothing.json", "cannot open"});
}

}  // namespace
}  // namespace dp
