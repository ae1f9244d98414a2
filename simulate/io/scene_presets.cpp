#include "scene_presets.h"

#include "json_reader.h"

namespace dp::io {

namespace {

std::string known_names(const nlohmann::json& presets) {
  std::string names;
  for (const auto& [name, patch] : presets.items()) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

}  // namespace

nlohmann::json apply_preset(const nlohmann::json& document, const std::string& preset, const std::filesystem::path& file) {
  nlohmann::json result = document;
  nlohmann::json presets = nlohmann::json::object();
  if (result.is_object() && result.contains("presets")) {
    presets = result["presets"];
    result.erase("presets");
    // Validates the shape only; each patch is checked with the scene it makes.
    const nlohmann::json wrapper{{"presets", presets}};
    JsonObject top(wrapper, "", file);
    top.entries("presets");
  }
  if (preset.empty()) return result;
  if (!presets.contains(preset))
    throw SceneError(file.string() + ": presets: no preset '" + preset + "' (this scene has: " + known_names(presets) + ")");
  // merge_patch is nlohmann's RFC 7386: objects merge key by key, null
  // deletes, anything else (arrays included) replaces.
  result.merge_patch(presets[preset]);
  return result;
}

}  // namespace dp::io
