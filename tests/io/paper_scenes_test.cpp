// The paper's scenes (assets/scenes/, Hochstetter & Kolb 2017 Sec. 8): every
// file and every preset loads and validates, and at full quality the scenes
// have the resolutions of the paper's Table 1 (particle counts within 10 %).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "rigid/sample_surface.h"
#include "scene.h"
#include "simulation_setup.h"
#include "triangle_mesh.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

const fs::path kScenes = fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes";

// One row of Table 1; 0 where the paper has '-'.
struct Table1Row {
  const char* scene;
  double liquid, rigid;
  int cells, texels;
};
const Table1Row kTable1[] = {
    {"drop_notex", 1207, 5108, 64, 0},   {"drop", 1207, 5108, 64, 512},
    {"sca_logo_tex", 0, 28000, 64, 1024}, {"sca_logo", 0, 28000, 64, 1024},  // SCA Logo's 135 are emitted later
    {"glass", 174000, 89000, 64, 1024},
};

// Names the row in test output instead of its bytes.
void PrintTo(const Table1Row& row, std::ostream* os) { *os << row.scene; }

std::size_t liquid_count(const Scene& s) {
  std::size_t n = 0;
  for (const LiquidBlock& b : s.simulation.liquid_blocks) n += fill_block(b, s.simulation.particle_spacing_m).size();
  return n;
}

// What dewpoint-simulate samples, without building the textures.
std::size_t rigid_count(const Scene& s) {
  std::size_t n = 0;
  for (const RigidObject& r : s.simulation.rigids) {
    const TriangleMesh mesh = load_triangle_mesh(r.mesh);
    n += sample_surface(mesh.positions, mesh.triangles, static_cast<float>(s.simulation.particle_spacing_m)).size();
  }
  return n;
}

void expect_within_10_percent(double ours, double paper, const std::string& what) {
  if (paper == 0) {
    EXPECT_EQ(ours, 0) << what;
    return;
  }
  EXPECT_LE(std::abs(ours - paper), 0.1 * paper) << what << ": ours " << ours << ", paper " << paper;
}

class PaperScene : public ::testing::TestWithParam<Table1Row> {};

TEST_P(PaperScene, HasTheResolutionsOfTable1) {
  const Table1Row& row = GetParam();
  const Scene s = load_scene(kScenes / (std::string(row.scene) + ".json"));
  expect_within_10_percent(static_cast<double>(liquid_count(s)), row.liquid, std::string(row.scene) + " #Ptcl");
  expect_within_10_percent(static_cast<double>(rigid_count(s)), row.rigid, std::string(row.scene) + " #RigPtcl");
  ASSERT_TRUE(s.simulation.air.has_value());
  EXPECT_EQ(s.simulation.air->resolution, row.cells);
  int textured = 0;
  for (const RigidObject& r : s.simulation.rigids)
    if (r.texture) {
      ++textured;
      EXPECT_EQ(r.texture->width, row.texels);
      EXPECT_EQ(r.texture->height, row.texels);
    }
  EXPECT_EQ(textured, row.texels > 0 ? 1 : 0);
}

TEST_P(PaperScene, EveryPresetLoadsAndValidates) {
  const fs::path file = kScenes / (std::string(GetParam().scene) + ".json");
  std::ifstream in(file);
  const nlohmann::json doc = nlohmann::json::parse(in);
  ASSERT_TRUE(doc.contains("presets"));
  EXPECT_TRUE(doc["presets"].contains("preview"));
  EXPECT_TRUE(doc["presets"].contains("table1"));
  for (const auto& [name, patch] : doc["presets"].items()) {
    const Scene s = load_scene(file, name);
    EXPECT_EQ(s.preset, name);
    if (name == "table1") {  // the timing run keeps the paper's resolution
      const Scene full = load_scene(file);
      EXPECT_EQ(s.simulation.particle_spacing_m, full.simulation.particle_spacing_m);
      EXPECT_EQ(s.simulation.air->resolution, full.simulation.air->resolution);
      EXPECT_EQ(s.simulation.time_step_s, full.simulation.time_step_s);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Table1, PaperScene, ::testing::ValuesIn(kTable1),
                         [](const ::testing::TestParamInfo<Table1Row>& info) { return std::string(info.param.scene); });

// Paper Table 1's dtau column: 4, 4, 5, 5, 2 ms, the bound of the CFL step
// (fixed steps this long are unstable at these spacings when the drop lands).
TEST(PaperScenes, TimeStepsAreThePapers) {
  const std::pair<const char*, double> steps[] = {
      {"drop_notex", 0.004}, {"drop", 0.004}, {"sca_logo_tex", 0.005}, {"sca_logo", 0.005}, {"glass", 0.002}};
  for (const auto& [name, dt] : steps) {
    const Scene s = load_scene(kScenes / (std::string(name) + ".json"));
    EXPECT_DOUBLE_EQ(s.simulation.time_step_s, dt) << name;
    EXPECT_TRUE(s.simulation.cfl_time_step) << name;
  }
}

TEST(PaperScenes, ContactAnglesSceneHasOneParticlePerDrop) {
  for (const std::string preset : {"", "preview"}) {
    const Scene s = load_scene(kScenes / "contact_angles.json", preset);
    EXPECT_EQ(liquid_count(s), 4u);
    for (const LiquidBlock& b : s.simulation.liquid_blocks) EXPECT_EQ(fill_block(b, s.simulation.particle_spacing_m).size(), 1u);
  }
}

}  // namespace
}  // namespace dp::io
