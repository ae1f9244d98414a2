// --preset on the three executables (docs/scene-format.md, "Presets") and
// scenes without liquid, as users run them.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace dp {
namespace {

const fs::path kSource = DEWPOINT_SOURCE_DIR;

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

class PresetCli : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = dp::test::test_folder("dewpoint-preset-cli-");
    fs::remove_all(work_);
    fs::create_directories(work_);
  }
  // An asset scene's rigids with their mesh and image paths made absolute.
  static void make_rigid_paths_absolute(nlohmann::json& rigids) {
    const fs::path dir = kSource / "assets/scenes";
    for (auto& r : rigids) {
      r["mesh"] = (dir / r["mesh"].get<std::string>()).lexically_normal().string();
      if (r.contains("texture") && r["texture"].contains("max_mass_image"))
        r["texture"]["max_mass_image"] = (dir / r["texture"]["max_mass_image"].get<std::string>()).lexically_normal().string();
    }
  }
  // A copy of an asset scene in the work folder, its relative paths made absolute.
  fs::path copy_scene(const std::string& name, const nlohmann::json& presets) {
    nlohmann::json doc = read_json(kSource / "assets/scenes" / (name + ".json"));
    make_rigid_paths_absolute(doc["simulation"]["rigids"]);
    doc["presets"] = presets;
    const fs::path file = work_ / (name + ".json");
    std::ofstream(file) << doc.dump(2);
    return file;
  }
  fs::path work_;
};

TEST_F(PresetCli, SimulateRecordsThePresetAndMeshAndRenderApplyIt) {
  const nlohmann::json coarse = {{"simulation", {{"particle_spacing_m", 0.025}, {"duration_s", 0.05}, {"frame_rate_hz", 20}}},
                                 {"mesh", {{"voxels_per_radius", 1}}},
                                 {"render", {{"resolution", {32, 18}}, {"spp", 1}}}};
  const fs::path scene = copy_scene("demo", {{"coarse", coarse}});
  const auto sim = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " -o " + (work_ / "shot").string() +
                                     " --preset coarse --quiet");
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const nlohmann::json manifest = read_json(work_ / "shot/frames/manifest.json");
  EXPECT_EQ(manifest["preset"], "coarse");
  EXPECT_EQ(manifest["particle_spacing_m"], 0.025);
  EXPECT_FALSE(manifest["scene"].contains("presets"));

  // The mesher takes the recorded preset: voxel = radius (0.5 spacing) / 1.
  const auto mesh = test::run_command(std::string(DEWPOINT_MESH) + " " + (work_ / "shot/frames").string() + " -o " +
                                      (work_ / "shot/meshes").string() + " --frames 1 --quiet");
  ASSERT_EQ(mesh.exit_code, 0) << mesh.output;
  EXPECT_DOUBLE_EQ(read_json(work_ / "shot/meshes/liquid.0001.json")["voxel_size_m"].get<double>(), 0.0125);

  const auto render = test::run_command(std::string(DEWPOINT_RENDER) + " " + scene.string() + " --frames-dir " +
                                        (work_ / "shot/frames").string() + " --meshes-dir " + (work_ / "shot/meshes").string() +
                                        " -o " + (work_ / "shot/images").string() + " --frames 1 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  const nlohmann::json sidecar = read_json(work_ / "shot/images/beauty.0001.json");
  EXPECT_EQ(sidecar["resolution"], nlohmann::json({32, 18}));
  EXPECT_EQ(sidecar["spp"], 1);
}

// --duration lengthens a preset's shot (pipelines/gpu-shot.sh runs table1
// for a whole second) and changes nothing but where it ends.
TEST_F(PresetCli, DurationExtendsTheShotAndLeavesItsFramesAsTheyWere) {
  const nlohmann::json coarse = {{"simulation", {{"particle_spacing_m", 0.025}, {"duration_s", 0.05}, {"frame_rate_hz", 20}}}};
  const fs::path scene = copy_scene("demo", {{"coarse", coarse}});
  const std::string run = std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " --preset coarse --quiet -o ";
  const auto short_run = test::run_command(run + (work_ / "short").string());
  ASSERT_EQ(short_run.exit_code, 0) << short_run.output;
  const auto long_run = test::run_command(run + (work_ / "long").string() + " --duration 0.1");
  ASSERT_EQ(long_run.exit_code, 0) << long_run.output;
  const nlohmann::json manifest = read_json(work_ / "long/frames/manifest.json");
  ASSERT_EQ(manifest["frames"].size(), 3u);  // 0.1 s at 20 Hz: frames 0, 1, 2
  EXPECT_EQ(read_json(work_ / "short/frames/manifest.json")["frames"].size(), 2u);
  EXPECT_EQ(manifest["settings"]["duration_s"], 0.1);
  const auto bytes = [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* frame : {"particles.0000.ply", "particles.0001.ply"})
    EXPECT_EQ(bytes(work_ / "short/frames" / frame), bytes(work_ / "long/frames" / frame)) << frame;

  const auto refused = test::run_command(run + (work_ / "none").string() + " --duration 0");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("--duration"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(work_ / "none"));
}

TEST_F(PresetCli, UnknownPresetIsRefusedByEveryToolBeforeAnyOutput) {
  const fs::path scene = copy_scene("demo", {{"preview", nlohmann::json::object()}});
  const auto sim = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " -o " + (work_ / "shot").string() +
                                     " --preset fnial --quiet");
  EXPECT_EQ(sim.exit_code, 2);
  EXPECT_NE(sim.output.find(scene.string() + ": presets: no preset 'fnial' (this scene has: preview)"), std::string::npos)
      << sim.output;
  EXPECT_FALSE(fs::exists(work_ / "shot"));
}

TEST_F(PresetCli, TextureOnlySceneRunsWithoutLiquid) {
  // The paper's SCA Logo Tex: no liquid particles, water only in the mirror's texture.
  // The scene's rigids with a small texture: a preset replaces the whole array.
  nlohmann::json rigids = read_json(kSource / "assets/scenes/sca_logo_tex.json")["simulation"]["rigids"];
  make_rigid_paths_absolute(rigids);
  rigids[0]["texture"] = {{"resolution", {64, 64}}};
  const fs::path scene = copy_scene(
      "sca_logo_tex",
      {{"short", {{"simulation", {{"duration_s", 0.02}, {"frame_rate_hz", 100}, {"air", {{"resolution", 32}}}, {"rigids", rigids}}}}}});
  const auto sim = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " -o " + (work_ / "shot").string() +
                                     " --preset short --quiet");
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const nlohmann::json manifest = read_json(work_ / "shot/frames/manifest.json");
  ASSERT_EQ(manifest["frames"].size(), 3u);
  for (const auto& frame : manifest["frames"]) EXPECT_EQ(frame["liquid_particles"], 0);
  // Humid air on a 4 degC mirror: water condenses into the texture and the ledger balances.
  const auto& water = manifest["frames"].back()["water"];
  EXPECT_GT(water["texels_kg"].get<double>(), 0.0);
  EXPECT_LE(std::abs(water["relative_drift"].get<double>()), 1e-9);
}

TEST_F(PresetCli, SoakedLettersEmitDropsThatStayInTheBasin) {
  // The paper's SCA Logo (Fig. 7) at its preview spacing with a small texture: the
  // pre-soaked letters emit particles (Alg. 1 line 17), which must run down into the
  // basin (floor y = -12 mm, walls at |x| = 166 mm, |z| = 40 mm) and not leave it.
  nlohmann::json doc = read_json(kSource / "assets/scenes/sca_logo.json");
  nlohmann::json rigids = doc["presets"]["preview"]["simulation"]["rigids"];
  make_rigid_paths_absolute(rigids);
  rigids[0]["texture"]["resolution"] = {128, 128};
  const fs::path scene = copy_scene(
      "sca_logo", {{"short",
                    {{"simulation",
                      {{"particle_spacing_m", 0.004}, {"duration_s", 0.4}, {"frame_rate_hz", 5}, {"air", {{"resolution", 32}}}, {"rigids", rigids}}}}}});
  const auto sim = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " -o " + (work_ / "shot").string() +
                                     " --preset short --quiet");
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const nlohmann::json manifest = read_json(work_ / "shot/frames/manifest.json");
  const auto& last = manifest["frames"].back();
  EXPECT_GT(last["liquid_particles"].get<int>(), 0);
  EXPECT_GT(last["water"]["liquid_kg"].get<double>(), 0.0);
  EXPECT_LE(std::abs(last["water"]["relative_drift"].get<double>()), 1e-9);
  // The positions straight from the binary PLY (docs/file-formats.md: x, y, z first, 4-byte properties).
  std::ifstream ply(work_ / "shot/frames" / last["files"]["particles"].get<std::string>(), std::ios::binary);
  std::string line;
  std::size_t count = 0, properties = 0;
  while (std::getline(ply, line) && line != "end_header") {
    if (line.rfind("element vertex ", 0) == 0) count = std::stoul(line.substr(15));
    if (line.rfind("property ", 0) == 0) ++properties;
  }
  ASSERT_EQ(count, last["liquid_particles"].get<std::size_t>());
  std::vector<char> row(4 * properties);
  std::size_t read = 0, below_floor = 0, outside_walls = 0;
  while (read < count && ply.read(row.data(), static_cast<std::streamsize>(row.size()))) {
    float x[3];
    std::memcpy(x, row.data(), sizeof x);
    ++read;
    below_floor += x[1] < -0.012f;
    outside_walls += std::abs(x[0]) > 0.166f || std::abs(x[2]) > 0.040f;
  }
  EXPECT_EQ(read, count);
  EXPECT_EQ(below_floor, 0u);
  EXPECT_EQ(outside_walls, 0u);
}

TEST_F(PresetCli, SceneWithoutLiquidOrTextureIsRefused) {
  nlohmann::json doc = read_json(kSource / "assets/scenes/demo.json");
  doc["simulation"]["liquid_blocks"] = nlohmann::json::array();
  doc["simulation"]["rigids"][0]["mesh"] = (kSource / "assets/meshes/tray.obj").string();
  const fs::path scene = work_ / "dry.json";
  std::ofstream(scene) << doc.dump(2);
  const auto sim = test::run_command(std::string(DEWPOINT_SIMULATE) + " " + scene.string() + " -o " + (work_ / "shot").string());
  EXPECT_EQ(sim.exit_code, 2);
  EXPECT_NE(sim.output.find("dry.json: simulation.liquid_blocks: no liquid particles and no textured rigid"), std::string::npos)
      << sim.output;
  EXPECT_FALSE(fs::exists(work_ / "shot"));
}

}  // namespace
}  // namespace dp
