#pragma once
// Named variants of one scene file: `"presets": {"NAME": PATCH}` at the top
// level, each PATCH a JSON merge patch (RFC 7386) applied to the document
// before it is validated (docs/scene-format.md, "Presets").
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace dp::io {

// The document with `presets` removed and, unless `preset` is empty, that
// preset's patch merged in. Throws SceneError naming the file when
// `presets` is not an object of objects or `preset` is not one of them.
nlohmann::json apply_preset(const nlohmann::json& document, const std::string& preset,
                            const std::filesystem::path& file);

}  // namespace dp::io
