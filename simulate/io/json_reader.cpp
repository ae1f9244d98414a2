#include "json_reader.h"

#include "unit_suffix.h"

namespace dp::io {

namespace {
std::string kind_of(const nlohmann::json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number_integer() || v.is_number_unsigned()) return "an integer";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array of " + std::to_string(v.size());
  return "an object";
}
}  // namespace

JsonObject::JsonObject(const nlohmann::json& value, std::string key_path, std::filesystem::path file)
    : value_(value), key_path_(std::move(key_path)), file_(std::move(file)) {
  if (!value_.is_object())
    throw SceneError(file_.string() + ": " + (key_path_.empty() ? "top level" : key_path_) + ": expected an object, found " + kind_of(value_));
}

std::string JsonObject::path_of(const std::string& key) const { return key_path_.empty() ? key : key_path_ + "." + key; }

SceneError JsonObject::error(const std::string& key, const std::string& problem) const {
  return SceneError(file_.string() + ": " + path_of(key) + ": " + problem);
}

bool JsonObject::has(const std::string& key) const { return value_.contains(key); }

const nlohmann::json* JsonObject::find(const std::string& key) {
  used_.insert(key);
  auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

const nlohmann::json& JsonObject::get(const std::string& key, const char* expected) {
  const nlohmann::json* v = find(key);
  if (!v) throw error(key, std::string("missing required key (expected ") + expected + ")");
  return *v;
}

double JsonObject::number(const std::string& key) {
  const auto& v = get(key, "a number");
  if (!v.is_number()) throw error(key, "expected a number, found " + kind_of(v));
  return v.get<double>();
}
double JsonObject::number(const std::string& key, double fallback) { return has(key) ? number(key) : (used_.insert(key), fallback); }

std::int64_t JsonObject::integer(const std::string& key) {
  const auto& v = get(key, "an integer");
  if (!v.is_number_integer() && !v.is_number_unsigned()) throw error(key, "expected an integer, found " + kind_of(v));
  return v.get<std::int64_t>();
}
std::int64_t JsonObject::integer(const std::string& key, std::int64_t fallback) {
  return has(key) ? integer(key) : (used_.insert(key), fallback);
}

std::string JsonObject::string(const std::string& key) {
  const auto& v = get(key, "a string");
  if (!v.is_string()) throw error(key, "expected a string, found " + kind_of(v));
  return v.get<std::string>();
}
std::string JsonObject::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : (used_.insert(key), fallback);
}

bool JsonObject::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return used_.insert(key), fallback;
  const auto& v = get(key, "a boolean");
  if (!v.is_boolean()) throw error(key, "expected a boolean, found " + kind_of(v));
  return v.get<bool>();
}

std::array<double, 3> JsonObject::vec3(const std::string& key) {
  const auto& v = get(key, "an array of 3 numbers");
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw error(key, "expected an array of 3 numbers, found " + kind_of(v));
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}
std::array<double, 3> JsonObject::vec3(const std::string& key, std::array<double, 3> fallback) {
  return has(key) ? vec3(key) : (used_.insert(key), fallback);
}

std::array<std::int64_t, 2> JsonObject::int2(const std::string& key) {
  const auto& v = get(key, "an array of 2 integers");
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
    throw error(key, "expected an array of 2 integers, found " + kind_of(v));
  return {v[0].get<std::int64_t>(), v[1].get<std::int64_t>()};
}

JsonObject JsonObject::object(const std::string& key) {
  return JsonObject(get(key, "an object"), path_of(key), file_);
}

std::optional<JsonObject> JsonObject::optional_object(const std::string& key) {
  if (!has(key)) {
    used_.insert(key);
    return std::nullopt;
  }
  return object(key);
}

std::vector<JsonObject> JsonObject::objects(const std::string& key) {
  const auto& v = get(key, "an array of objects");
  if (!v.is_array()) throw error(key, "expected an array of objects, found " + kind_of(v));
  std::vector<JsonObject> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.emplace_back(v[i], path_of(key) + "[" + std::to_string(i) + "]", file_);
  return out;
}

std::vector<std::pair<std::string, JsonObject>> JsonObject::entries(const std::string& key) {
  const auto& v = get(key, "an object");
  if (!v.is_object()) throw error(key, "expected an object, found " + kind_of(v));
  std::vector<std::pair<std::string, JsonObject>> out;
  for (auto it = v.begin(); it != v.end(); ++it) out.emplace_back(it.key(), JsonObject(it.value(), path_of(key) + "." + it.key(), file_));
  return out;
}

void JsonObject::finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (used_.count(it.key())) continue;
    if (const auto expected = key_in_expected_unit(it.key(), used_))
      throw SceneError(file_.string() + ": " + path_of(it.key()) + ": wrong unit: expected " + path_of(*expected) +
                       " (the unit is the key's suffix), found " + it.key() + " = " + it.value().dump());
    std::string known;
    for (const auto& k : used_) known += (known.empty() ? "" : ", ") + k;
    throw SceneError(file_.string() + ": " + path_of(it.key()) + ": unknown key (known keys here: " + known + ")");
  }
}

}  // namespace dp::io
