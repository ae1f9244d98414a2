#pragma once
// Scene keys end in their unit (particle_spacing_m, temperature_c,
// max_speed_m_s): a key that differs from a known one only in that suffix
// is a value in the wrong unit, worth saying so rather than "unknown key".
#include <optional>
#include <set>
#include <string>

namespace dp::io {

// The known key that `key` would be in the unit the format expects, when
// `key` is one of `known` with another unit suffix (temperature_k for
// temperature_c); none otherwise.
std::optional<std::string> key_in_expected_unit(const std::string& key, const std::set<std::string>& known);

}  // namespace dp::io
