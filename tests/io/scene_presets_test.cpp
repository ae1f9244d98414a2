// Scene presets (docs/scene-format.md, "Presets"): a preset is an RFC 7386
// JSON merge patch applied before validation. The merge cases are the
// RFC's own examples (RFC 7386, Appendix A); the rest checks that patched
// values reach the settings and that bad presets are reported.
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene.h"
#include "scene_presets.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

const fs::path kDemo = fs::path(DEWPOINT_SOURCE_DIR) / "assets/scenes/demo.json";

nlohmann::json demo_with_presets(const nlohmann::json& presets) {
  std::ifstream in(kDemo);
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["presets"] = presets;
  return doc;
}

// Beside the demo scene, so its relative mesh path resolves.
fs::path write_beside_demo(const nlohmann::json& doc, const std::string& name) {
  const fs::path file = fs::temp_directory_path() / ("dewpoint-preset-test-" + std::to_string(getpid())) / "scenes" / name;
  fs::create_directories(file.parent_path());
  fs::create_directories(file.parent_path().parent_path() / "meshes");
  fs::copy_file(fs::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj", file.parent_path().parent_path() / "meshes/tray.obj",
                fs::copy_options::overwrite_existing);
  std::ofstream(file) << doc.dump(2);
  return file;
}

std::string load_error(const fs::path& file, const std::string& preset) {
  try {
    load_scene(file, preset);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// RFC 7386 Appendix A: ORIGINAL, PATCH, RESULT.
TEST(ScenePresets, MergeFollowsRfc7386AppendixA) {
  const char* cases[][3] = {
      {R"({"a":"b"})", R"({"a":"c"})", R"({"a":"c"})"},
      {R"({"a":"b"})", R"({"b":"c"})", R"({"a":"b","b":"c"})"},
      {R"({"a":"b"})", R"({"a":null})", R"({})"},
      {R"({"a":"b","b":"c"})", R"({"a":null})", R"({"b":"c"})"},
      {R"({"a":["b"]})", R"({"a":"c"})", R"({"a":"c"})"},
      {R"({"a":"c"})", R"({"a":["b"]})", R"({"a":["b"]})"},
      {R"({"a":{"b":"c"}})", R"({"a":{"b":"d","c":null}})", R"({"a":{"b":"d"}})"},
      {R"({"a":[{"b":"c"}]})", R"({"a":[1]})", R"({"a":[1]})"},
      {R"({"e":null})", R"({"a":1})", R"({"e":null,"a":1})"},
      {R"({})", R"({"a":{"bb":{"ccc":null}}})", R"({"a":{"bb":{}}})"},
  };
  for (const auto& c : cases) {
    nlohmann::json doc = nlohmann::json::parse(c[0]);
    doc["presets"] = {{"p", nlohmann::json::parse(c[1])}};
    EXPECT_EQ(apply_preset(doc, "p", "x.json"), nlohmann::json::parse(c[2])) << c[0] << " + " << c[1];
  }
}

TEST(ScenePresets, PatchedValuesReachTheSettingsAndTheRestStays) {
  const fs::path file = write_beside_demo(
      demo_with_presets({{"fast", {{"simulation", {{"particle_spacing_m", 0.025}, {"liquid", {{"temperature_c", 30}}}}},
                                   {"render", {{"spp", 4}}}}}}),
      "preset_values.json");
  const Scene plain = load_scene(file);
  const Scene fast = load_scene(file, "fast");
  EXPECT_EQ(plain.preset, "");
  EXPECT_EQ(fast.preset, "fast");
  EXPECT_DOUBLE_EQ(plain.simulation.particle_spacing_m, 0.0125);
  EXPECT_DOUBLE_EQ(fast.simulation.particle_spacing_m, 0.025);
  EXPECT_DOUBLE_EQ(fast.simulation.liquid.temperature_k, 303.15);
  EXPECT_EQ(fast.render.spp, 4);
  // Merged, not replaced: the liquid's other keys and the other sections are the file's.
  EXPECT_DOUBLE_EQ(fast.simulation.liquid.surface_tension, plain.simulation.liquid.surface_tension);
  EXPECT_DOUBLE_EQ(fast.simulation.liquid.boundary_friction, plain.simulation.liquid.boundary_friction);
  EXPECT_EQ(fast.render.width, plain.render.width);
  EXPECT_EQ(fast.render.height, plain.render.height);
  // The document recorded in outputs is the one run, without the presets.
  EXPECT_FALSE(fast.document.contains("presets"));
  EXPECT_EQ(fast.document["simulation"]["particle_spacing_m"], 0.025);
}

TEST(ScenePresets, UnknownPresetNamesTheFileAndThePresets) {
  const fs::path file = write_beside_demo(demo_with_presets({{"preview", nlohmann::json::object()}}), "preset_unknown.json");
  const std::string e = load_error(file, "final");
  EXPECT_NE(e.find("preset_unknown.json"), std::string::npos) << e;
  EXPECT_NE(e.find("no preset 'final'"), std::string::npos) << e;
  EXPECT_NE(e.find("preview"), std::string::npos) << e;
}

TEST(ScenePresets, PresetOnAFileWithoutPresetsIsAnError) {
  const std::string e = load_error(kDemo, "preview");
  EXPECT_NE(e.find("demo.json"), std::string::npos) << e;
  EXPECT_NE(e.find("no preset 'preview'"), std::string::npos) << e;
}

TEST(ScenePresets, BadPatchIsReportedAtItsKeyWithThePreset) {
  const fs::path file = write_beside_demo(
      demo_with_presets({{"bad", {{"simulation", {{"particle_spacing_m", "coarse"}}}}},
                         {"typo", {{"simulation", {{"particle_spacing", 0.02}}}}},
                         {"gone", {{"simulation", {{"particle_spacing_m", nullptr}}}}}}),
      "preset_bad.json");
  std::string e = load_error(file, "bad");
  EXPECT_NE(e.find("preset_bad.json: simulation.particle_spacing_m: expected a number, found a string"), std::string::npos) << e;
  EXPECT_NE(e.find("(with preset 'bad')"), std::string::npos) << e;
  e = load_error(file, "typo");
  EXPECT_NE(e.find("simulation.particle_spacing: unknown key"), std::string::npos) << e;
  EXPECT_NE(e.find("(with preset 'typo')"), std::string::npos) << e;
  e = load_error(file, "gone");  // null deletes a required key
  EXPECT_NE(e.find("simulation.particle_spacing_m: missing required key"), std::string::npos) << e;
  // Without a preset the file itself is fine.
  EXPECT_NO_THROW(load_scene(file));
}

TEST(ScenePresets, PresetsMustBeAnObjectOfObjects) {
  std::string e = load_error(write_beside_demo(demo_with_presets({1, 2}), "presets_array.json"), "");
  EXPECT_NE(e.find("presets_array.json: presets: expected an object, found an array of 2"), std::string::npos) << e;
  e = load_error(write_beside_demo(demo_with_presets({{"preview", 3}}), "presets_number.json"), "preview");
  EXPECT_NE(e.find("presets_number.json: presets.preview: expected an object, found an integer"), std::string::npos) << e;
}

}  // namespace
}  // namespace dp::io
