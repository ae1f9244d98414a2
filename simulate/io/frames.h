#pragma once
// The frames folder (docs/file-formats.md): particle PLYs per frame, rigid
// particles once, and manifest.json describing them.
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "simulation.h"

namespace dp::io {

// "particles.0007.ply" for kind "particles" and frame 7.
std::string frame_file_name(const std::string& kind, int frame, const std::string& extension);

// Sizes follow mass weights (paper Sec. 4.1): the radius of a particle of
// mass weight w scales with w^(1/3).
inline float particle_radius_of(float full_particle_radius, float weight) { return full_particle_radius * std::cbrt(weight); }

void write_particle_frame(const std::filesystem::path& file, const ParticleSnapshot& particles, float particle_radius,
                          const std::string& comment);
void write_rigid_particles(const std::filesystem::path& file, const std::vector<Vec3>& position,
                           const std::vector<float>& volume, const std::vector<float>& temperature,
                           const std::string& comment);

struct FrameEntry {
  int index = 0;
  double time_s = 0;
  std::int64_t step = 0;
  std::size_t liquid_particles = 0;
  std::string particles_file;  // relative to the frames folder
  std::string air_file{};      // air.%04d.vdb; empty: no air phase
  nlohmann::json air_vapor{};  // the air's vapor ledger (kg); null: no air phase
  nlohmann::json water{};      // the water ledger (kg, simulate/core/coupling/water_ledger.h); null: none
  std::map<std::string, std::string> surface_files{};  // rigid name -> surface_NAME.%04d.exr
};

// A textured rigid (docs/file-formats.md): its atlas mesh and texture size.
struct RigidSurfaceEntry {
  std::string name;
  std::string mesh_file;  // rigid_NAME.ply
  std::array<int, 2> texture_resolution{0, 0};
};

struct FramesManifest {
  std::filesystem::path scene_file;
  std::string scene_name;
  double particle_spacing_m = 0;
  double particle_radius_m = 0;
  std::string rigid_particles_file;
  std::vector<RigidSurfaceEntry> rigids;
  std::vector<FrameEntry> frames;
  nlohmann::json extra;  // generator, settings, the scene document
};

void write_manifest(const std::filesystem::path& frames_dir, const FramesManifest& manifest);
// Throws std::runtime_error naming the file and key when it is not a manifest.
FramesManifest read_manifest(const std::filesystem::path& frames_dir);

// The scene preset the frames were simulated with (manifest key `preset`);
// empty when none was.
std::string recorded_preset(const FramesManifest& manifest);

}  // namespace dp::io
