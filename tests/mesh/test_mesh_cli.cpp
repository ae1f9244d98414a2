// dewpoint-mesh as a user runs it: on a tiny frames folder made here, and on
// broken ones.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "dewpoint/version.h"
#include <openvdb/openvdb.h>

#include "frames.h"
#include "ply.h"

namespace fs = std::filesystem;

namespace {

const fs::path kMesher = fs::path(DEWPOINT_BINARY_DIR) / "mesh" / "dewpoint-mesh";
const fs::path kScene = fs::path(DEWPOINT_SOURCE_DIR) / "assets" / "scenes" / "demo.json";
constexpr double kSpacing = 0.0125;  // the demo scene's

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct MesherRun {
  int exit_code;
  std::string out, err;
};

class mesh_Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dp::test::test_folder("dewpoint-mesh-test-" + std::to_string(::getpid()) + "-");
    fs::remove_all(dir_);
    fs::create_directories(frames_dir());
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  fs::path frames_dir() const { return dir_ / "frames"; }
  fs::path out_dir() const { return dir_ / "meshes"; }

  // A 4x4x4 block of liquid particles at the demo's spacing as frame 0,
  // its lowest layer `floor_gap` above the demo tray's floor (y = 0).
  void write_tiny_frames(double floor_gap = 0.05) {
    dp::io::PlyData ply;
    std::vector<double> x, y, z, w;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          x.push_back(i * kSpacing);
          y.push_back(floor_gap + j * kSpacing);
          z.push_back(k * kSpacing);
          w.push_back(1.0);
        }
    ply.vertex_count = x.size();
    ply.add("x", dp::io::PlyType::Float32, x);
    ply.add("y", dp::io::PlyType::Float32, y);
    ply.add("z", dp::io::PlyType::Float32, z);
    ply.add("weight", dp::io::PlyType::Float32, w);
    dp::io::write_ply(frames_dir() / dp::io::frame_file_name("particles", 0, "ply"), ply);

    dp::io::FramesManifest manifest;
    manifest.scene_file = kScene;
    manifest.scene_name = "tiny";
    manifest.particle_spacing_m = kSpacing;
    manifest.particle_radius_m = 0.5 * kSpacing;
    manifest.rigid_particles_file = "rigid_particles.ply";
    dp::io::FrameEntry entry;
    entry.index = 0;
    entry.liquid_particles = x.size();
    entry.particles_file = dp::io::frame_file_name("particles", 0, "ply");
    manifest.frames.push_back(entry);
    dp::io::write_manifest(frames_dir(), manifest);
  }

  MesherRun mesher(const std::string& arguments) const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = "'" + kMesher.string() + "' " + arguments + " > '" + out.string() + "' 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
  }

  std::string quoted(const fs::path& p) const { return "'" + p.string() + "'"; }

  fs::path dir_;
};

TEST_F(mesh_Cli, MeshesATinyFramesFolder) {
  write_tiny_frames();
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "") << "--quiet still printed";

  const dp::io::PlyData mesh = dp::io::read_ply(out_dir() / "liquid.0000.ply");
  EXPECT_GT(mesh.vertex_count, 0u);
  EXPECT_FALSE(mesh.faces.empty());
  for (const char* property : {"x", "y", "z", "nx", "ny", "nz"}) EXPECT_NE(mesh.find(property), nullptr) << property;

  const auto sidecar = nlohmann::json::parse(read_text(out_dir() / "liquid.0000.json"));
  EXPECT_EQ(sidecar.at("frame").get<int>(), 0);
  EXPECT_EQ(sidecar.at("vertices").get<std::size_t>(), mesh.vertex_count);
  EXPECT_EQ(sidecar.at("triangles").get<std::size_t>(), mesh.faces.size());
  EXPECT_DOUBLE_EQ(sidecar.at("kernel_radius_m").get<double>(), 2 * kSpacing);
  EXPECT_DOUBLE_EQ(sidecar.at("voxel_size_m").get<double>(), 0.5 * kSpacing / 2);
  EXPECT_EQ(sidecar.at("generator").get<std::string>(), std::string("dewpoint-mesh ") + dp::kVersion);
  for (const char* key : {"seconds", "source_frames_dir", "enclosed_volume_m3"}) EXPECT_TRUE(sidecar.contains(key)) << key;
}

// --level-set: liquid.NNNN.vdb beside the mesh, a level set named "surface"
// whose voxels are the mesh's, recorded in the sidecar; without the flag
// (and the scene's mesh.level_set) no grid is written.
TEST_F(mesh_Cli, LevelSetFlagWritesTheFieldAsAnOpenVdbLevelSet) {
  write_tiny_frames();
  ASSERT_EQ(mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --quiet").exit_code, 0);
  EXPECT_FALSE(fs::exists(out_dir() / "liquid.0000.vdb"));
  EXPECT_TRUE(nlohmann::json::parse(read_text(out_dir() / "liquid.0000.json")).at("level_set_file").is_null());

  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --level-set --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto sidecar = nlohmann::json::parse(read_text(out_dir() / "liquid.0000.json"));
  EXPECT_EQ(sidecar.at("level_set_file").get<std::string>(), "liquid.0000.vdb");
  openvdb::initialize();
  openvdb::io::File file((out_dir() / "liquid.0000.vdb").string());
  file.open();
  const openvdb::GridBase::Ptr base = file.readGrid("surface");
  file.close();
  const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_DOUBLE_EQ(grid->voxelSize()[0], sidecar.at("voxel_size_m").get<double>());
  EXPECT_GT(grid->activeVoxelCount(), 0u);
  // Inside the liquid (below zero) somewhere, and zero crossings between.
  float lowest = 0;
  for (auto v = grid->cbeginValueOn(); v; ++v) lowest = std::min(lowest, *v);
  EXPECT_LT(lowest, 0.0f);
}

TEST_F(mesh_Cli, VoxelSizeOptionOverridesTheScene) {
  write_tiny_frames();
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --voxel-size 0.005 --threads 1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("mesh tiny 1/1"), std::string::npos) << "no progress line in: " << run.err;
  const auto sidecar = nlohmann::json::parse(read_text(out_dir() / "liquid.0000.json"));
  EXPECT_DOUBLE_EQ(sidecar.at("voxel_size_m").get<double>(), 0.005);
}

TEST_F(mesh_Cli, MissingManifestExitsWithCodeTwoNamingIt) {
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("dewpoint-mesh: " + (frames_dir() / "manifest.json").string() + ": ", 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(mesh_Cli, CorruptParticleFileExitsWithCodeTwoAndWritesNothing) {
  write_tiny_frames();
  const fs::path particles = frames_dir() / "particles.0000.ply";
  const std::string bytes = read_text(particles);
  std::ofstream(particles, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --quiet");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("dewpoint-mesh: " + particles.string() + ": ", 0), 0u) << run.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(mesh_Cli, BadFrameAfterGoodOnesStopsBeforeAnyOutput) {
  write_tiny_frames();
  dp::io::FramesManifest manifest = dp::io::read_manifest(frames_dir());
  dp::io::FrameEntry second = manifest.frames[0];
  second.index = 1;
  second.particles_file = dp::io::frame_file_name("particles", 1, "ply");
  manifest.frames.push_back(second);
  dp::io::write_manifest(frames_dir(), manifest);
  std::ofstream(frames_dir() / second.particles_file) << "ply\nformat binary_little_endian 1.0\nelement vertex 64\n";
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --quiet");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("dewpoint-mesh: " + (frames_dir() / second.particles_file).string() + ": ", 0), 0u) << run.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(mesh_Cli, FrameOutsideTheManifestExitsWithCodeTwo) {
  write_tiny_frames();
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --frames 5-9");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("dewpoint-mesh: " + (frames_dir() / "manifest.json").string() + ": ", 0), 0u) << run.err;
}

TEST_F(mesh_Cli, MissingParticleFileExitsWithCodeTwoNamingIt) {
  write_tiny_frames();
  fs::remove(frames_dir() / "particles.0000.ply");
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find((frames_dir() / "particles.0000.ply").string()), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(mesh_Cli, BadCommandLineExitsWithCodeTwoInOneLine) {
  const MesherRun run = mesher("--threads -1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("dewpoint-mesh: ", 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

double lowest_vertex_y(const fs::path& ply_file) {
  const dp::io::PlyData mesh = dp::io::read_ply(ply_file);
  const std::vector<float> y = mesh.floats("y");
  return *std::min_element(y.begin(), y.end());
}

// Paper Fig. 4 in numbers: the same frame meshed plain and corrected. The
// block rests 4 mm above the tray's floor, closer than a particle radius
// (6.25 mm): the plain spheres dip into the floor, the corrected surface
// stands on it.
TEST_F(mesh_Cli, CorrectedAndPlainMeshesOfTheSameFrame) {
  write_tiny_frames(0.004);
  const fs::path plain = dir_ / "plain", corrected = dir_ / "corrected";
  MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(plain) + " --quiet --no-correction");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  run = mesher(quoted(frames_dir()) + " -o " + quoted(corrected) + " --quiet --check --contact-angle 60");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const auto plain_sidecar = nlohmann::json::parse(read_text(plain / "liquid.0000.json"));
  const auto sidecar = nlohmann::json::parse(read_text(corrected / "liquid.0000.json"));
  EXPECT_FALSE(plain_sidecar.at("correction").at("enabled").get<bool>());
  const auto& correction = sidecar.at("correction");
  EXPECT_TRUE(correction.at("enabled").get<bool>());
  EXPECT_GT(correction.at("nodes_corrected").get<std::size_t>(), 0u);
  ASSERT_EQ(correction.at("rigids").size(), 1u);
  EXPECT_EQ(correction.at("rigids")[0].at("name").get<std::string>(), "tray");
  EXPECT_DOUBLE_EQ(correction.at("rigids")[0].at("contact_angle_deg").get<double>(), 60);
  EXPECT_TRUE(sidecar.at("check").at("passed").get<bool>()) << sidecar.at("check").dump();
  EXPECT_GT(sidecar.at("check").at("volume_m3").get<double>(), 0);

  EXPECT_LT(lowest_vertex_y(plain / "liquid.0000.ply"), -0.001);
  EXPECT_GE(lowest_vertex_y(corrected / "liquid.0000.ply"), -1e-6);
  EXPECT_LT(lowest_vertex_y(corrected / "liquid.0000.ply"), 1e-4);
}

TEST_F(mesh_Cli, ContactAngleOutOfRangeExitsWithCodeTwo) {
  write_tiny_frames();
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()) + " --contact-angle 200");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--contact-angle"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(mesh_Cli, SceneNamingAnUnknownRigidInMeshSectionExitsWithCodeTwo) {
  write_tiny_frames();
  auto scene = nlohmann::json::parse(read_text(kScene));
  scene["simulation"]["rigids"][0]["mesh"] = (kScene.parent_path() / "../meshes/tray.obj").lexically_normal().string();
  scene["mesh"]["rigids"] = {{"glass", {{"contact_angle_deg", 30}}}};
  const fs::path scene_file = dir_ / "scene.json";
  std::ofstream(scene_file) << scene.dump(2);
  dp::io::FramesManifest manifest = dp::io::read_manifest(frames_dir());
  manifest.scene_file = scene_file;
  dp::io::write_manifest(frames_dir(), manifest);
  const MesherRun run = mesher(quoted(frames_dir()) + " -o " + quoted(out_dir()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("dewpoint-mesh: " + scene_file.string() + ": mesh.rigids", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("'glass'"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(mesh_Cli, VersionNamesTheProgram) {
  const MesherRun run = mesher("--version");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, std::string("dewpoint-mesh ") + dp::kVersion + "\n");
}

}  // namespace
