#pragma once
// Reads one JSON object of a scene file and remembers which keys it used, so
// that unknown keys and wrong types are errors naming the file, the key's
// full path, what was expected and what was found.
#include <array>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dp::io {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class JsonObject {
 public:
  JsonObject(const nlohmann::json& value, std::string key_path, std::filesystem::path file);

  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  std::int64_t integer(const std::string& key);
  std::int64_t integer(const std::string& key, std::int64_t fallback);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  bool boolean(const std::string& key, bool fallback);
  std::array<double, 3> vec3(const std::string& key);
  std::array<double, 3> vec3(const std::string& key, std::array<double, 3> fallback);
  std::array<std::int64_t, 2> int2(const std::string& key);
  JsonObject object(const std::string& key);
  std::optional<JsonObject> optional_object(const std::string& key);
  std::vector<JsonObject> objects(const std::string& key);                    // array of objects
  std::vector<std::pair<std::string, JsonObject>> entries(const std::string& key);  // object of objects
  bool has(const std::string& key) const;

  // Throws on any key that no accessor asked for.
  void finish() const;

  // An error about `key` of this object, in the common format.
  SceneError error(const std::string& key, const std::string& problem) const;
  std::string path_of(const std::string& key) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  const nlohmann::json& get(const std::string& key, const char* expected);
  const nlohmann::json* find(const std::string& key);

  const nlohmann::json& value_;
  std::string key_path_;
  std::filesystem::path file_;
  std::set<std::string> used_;
};

}  // namespace dp::io
