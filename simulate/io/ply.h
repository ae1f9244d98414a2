#pragma once
// Binary little-endian PLY (the Stanford format), the particle and mesh
// contract between stages (docs/file-formats.md). Hand-written because
// Debian packages no PLY library and assimp drops named per-vertex
// properties; properties are read by name, so files may carry more than a
// reader asks for.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dp::io {

enum class PlyType { Float32, Float64, UInt8, Int32, UInt32 };

struct PlyProperty {
  std::string name;
  PlyType type;
  std::vector<double> values;  // one per vertex; exact for all types above
};

struct PlyData {
  std::vector<std::string> comments;
  std::size_t vertex_count = 0;
  std::vector<PlyProperty> vertex;                   // vertex properties in file order
  std::vector<std::array<std::uint32_t, 3>> faces;  // triangles, if any

  // Adds a property; values.size() must equal vertex_count.
  void add(const std::string& name, PlyType type, std::vector<double> values);
  const PlyProperty* find(const std::string& name) const;
  // Values of a named property as float; throws naming the file's missing property.
  std::vector<float> floats(const std::string& name) const;
};

// Writes atomically (temporary name, then rename).
void write_ply(const std::filesystem::path& path, const PlyData& data);
// Reads binary little-endian or ASCII PLY; throws std::runtime_error naming
// the file and what is wrong.
PlyData read_ply(const std::filesystem::path& path);

}  // namespace dp::io
