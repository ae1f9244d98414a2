// Checkpoints (docs/file-formats.md): a simulation's state survives
// encode -> decode -> restore unchanged (the bytes of a second encoding are
// the first's), a restored simulation steps on exactly as the original, and
// damaged files are recognised and passed over.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "../test_folder.h"
#include "checkpoint_folder.h"
#include "scene.h"
#include "simulation.h"
#include "simulation_setup.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

// The demo scene, small, with air, a textured tray holding water, and the
// coupling between them (every part of the state in use).
SimulationSetup coupled_setup(nlohmann::json* document = nullptr) {
  std::ifstream in(fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  auto& sim = doc["simulation"];
  sim["rigids"][0]["mesh"] = (fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj").string();
  sim["rigids"][0]["temperature_c"] = 45;
  sim["rigids"][0]["texture"] = {{"resolution", {32, 16}}, {"initial_mass_kg_m2", 0.02}};
  sim["liquid_blocks"][0]["min_m"] = {-0.0375, 0.03, -0.0375};
  sim["liquid_blocks"][0]["max_m"] = {0.0375, 0.08, 0.0375};
  sim["air"] = {{"resolution", 12}, {"boundary", {{"y_max", "open"}}}};
  const fs::path dir = dp::test::test_folder("dewpoint-checkpoint-test-");
  fs::create_directories(dir);
  std::ofstream(dir / "scene.json") << doc.dump(2);
  const Scene scene = load_scene(dir / "scene.json");
  if (document) *document = scene.document;
  return make_simulation_setup(scene);
}

std::unique_ptr<Simulation> simulation_of(const SimulationSetup& setup, int threads) {
  return make_simulation(ExecutionConfig{Device::Cpu, threads}, setup);
}

void advance(Simulation& s, int steps) {
  for (int i = 0; i < steps; ++i) s.step();
}

std::string encoded(const Simulation& s, int frame = 3) { return encode_checkpoint(Checkpoint{frame, 42, s.state()}); }

TEST(Checkpoint, SaveLoadSaveGivesTheSameBytes) {
  const SimulationSetup setup = coupled_setup();
  auto original = simulation_of(setup, 2);
  advance(*original, 12);
  const std::string first = encoded(*original);
  const Checkpoint loaded = decode_checkpoint(first, "memory");
  EXPECT_EQ(loaded.frame, 3);
  EXPECT_EQ(loaded.scene_hash, 42u);
  EXPECT_EQ(loaded.state.steps, 12);
  EXPECT_TRUE(loaded.state.has_air);
  ASSERT_EQ(loaded.state.surfaces.size(), 1u);
  EXPECT_EQ(encode_checkpoint(loaded), first) << "decode then encode";
  auto restored = simulation_of(setup, 2);
  restored->restore(loaded.state);
  EXPECT_EQ(encoded(*restored), first) << "restore into a fresh simulation, then encode";
}

TEST(Checkpoint, RestoredSimulationStepsOnBitForBit) {
  const SimulationSetup setup = coupled_setup();
  auto original = simulation_of(setup, 2);
  advance(*original, 10);
  const Checkpoint saved = decode_checkpoint(encoded(*original), "memory");
  // Another thread count too: CPU results must not depend on it.
  auto restored = simulation_of(setup, 1);
  restored->restore(saved.state);
  advance(*original, 15);
  advance(*restored, 15);
  EXPECT_EQ(encoded(*restored), encoded(*original));
  const WaterLedger w = original->water_ledger();
  EXPECT_GT(w.texels_to_air_kg + w.liquid_to_air_kg, 0.0) << "the coupling moved water, so its state was exercised";
}

TEST(Checkpoint, RestoreRefusesAStateOfAnotherSetup) {
  SimulationSetup setup = coupled_setup();
  auto original = simulation_of(setup, 1);
  SimulationState state = original->state();
  state.rigid_temperature.pop_back();
  EXPECT_THROW(simulation_of(setup, 1)->restore(state), std::invalid_argument);
  state = original->state();
  state.air.vapor.pop_back();
  EXPECT_THROW(simulation_of(setup, 1)->restore(state), std::invalid_argument);
}

TEST(Checkpoint, DamagedBytesAreRecognised) {
  auto s = simulation_of(coupled_setup(), 1);
  advance(*s, 2);
  const std::string good = encoded(*s);
  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  EXPECT_THROW(decode_checkpoint(flipped, "flipped"), CheckpointCorrupt);
  EXPECT_THROW(decode_checkpoint(good.substr(0, good.size() - 1), "short"), CheckpointCorrupt);
  EXPECT_THROW(decode_checkpoint(good.substr(0, 10), "header only"), CheckpointCorrupt);
  std::string other = good;
  other[0] = 'X';
  EXPECT_THROW(decode_checkpoint(other, "magic"), CheckpointCorrupt);
}

TEST(Checkpoint, FolderKeepsTwoAndSkipsACorruptNewest) {
  const fs::path dir = fs::temp_directory_path() / "dewpoint-checkpoint-folder-test";
  fs::remove_all(dir);
  nlohmann::json document;
  const SimulationSetup setup = coupled_setup(&document);
  auto s = simulation_of(setup, 1);
  const std::uint64_t hash = scene_document_hash(document);
  for (int frame = 1; frame <= 3; ++frame) {
    advance(*s, 2);
    save_checkpoint(dir, Checkpoint{frame, hash, s->state()});
  }
  EXPECT_FALSE(fs::exists(checkpoint_file(dir, 1))) << "only the newest two are kept";
  ASSERT_TRUE(fs::exists(checkpoint_file(dir, 2)));
  ASSERT_TRUE(fs::exists(checkpoint_file(dir, 3)));
  NewestCheckpoint newest = find_newest_checkpoint(dir);
  ASSERT_TRUE(newest.checkpoint);
  EXPECT_EQ(newest.checkpoint->frame, 3);
  EXPECT_TRUE(newest.skipped.empty());
  // A checkpoint cut short (as by a full disk or a copy interrupted).
  const fs::path latest = checkpoint_file(dir, 3);
  fs::resize_file(latest, fs::file_size(latest) / 2);
  newest = find_newest_checkpoint(dir);
  ASSERT_TRUE(newest.checkpoint);
  EXPECT_EQ(newest.checkpoint->frame, 2);
  ASSERT_EQ(newest.skipped.size(), 1u);
  EXPECT_NE(newest.skipped[0].find("checkpoint.000003.dpck"), std::string::npos) << newest.skipped[0];
  EXPECT_EQ(newest.checkpoint->scene_hash, hash);
  fs::remove(checkpoint_file(dir, 2));
  fs::resize_file(latest, 0);
  EXPECT_FALSE(find_newest_checkpoint(dir).checkpoint);
  EXPECT_FALSE(find_newest_checkpoint(dir / "absent").checkpoint);
}

TEST(Checkpoint, SceneHashFollowsTheDocument) {
  nlohmann::json a = {{"simulation", {{"duration_s", 1.0}}}};
  nlohmann::json b = a;
  EXPECT_EQ(scene_document_hash(a), scene_document_hash(b));
  b["simulation"]["duration_s"] = 1.5;
  EXPECT_NE(scene_document_hash(a), scene_document_hash(b));
}

}  // namespace
}  // namespace dp::io
