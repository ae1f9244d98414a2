#pragma once
// The JSON written beside each liquid mesh (docs/file-formats.md): what was
// meshed, with which parameters, and what came out. Written last, so its
// presence says the frame's mesh is complete.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact_angle_correction.h"
#include "liquid_surface.h"
#include "mesh_check.h"

namespace dp::mesh {

struct MeshSidecar {
  int frame = 0;
  double time_s = 0;
  std::filesystem::path frames_dir;
  std::string particles_file, mesh_file;
  std::string level_set_file;  // empty: none written
  std::filesystem::path scene_file;
  std::size_t liquid_particles = 0;
  SurfaceParameters parameters;
  int threads = 0;
  bool correction = false;
  std::vector<std::string> rigid_names;
  std::vector<std::filesystem::path> rigid_files;
  ContactAngleSettings angles;
  std::optional<MeshCheck> check;
  double read_seconds = 0, write_seconds = 0, check_seconds = 0;
  double walls_seconds = 0;  // loading the rigids and building their BVH, once per run
};

nlohmann::json mesh_sidecar_json(const MeshSidecar& sidecar, const LiquidSurface& surface);

// Written atomically.
void write_mesh_sidecar(const std::filesystem::path& file, const nlohmann::json& sidecar);

}  // namespace dp::mesh
