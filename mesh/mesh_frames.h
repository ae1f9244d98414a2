#pragma once
// dewpoint-mesh's work: every selected frame of a frames folder to a liquid
// mesh and its sidecar in the output folder.
#include <filesystem>
#include <optional>
#include <string>

#include "cli_common.h"

namespace dp::mesh {

struct MeshFramesOptions {
  std::filesystem::path frames_dir, out_dir;
  io::FrameRange range;
  double voxel_size = 0;         // > 0 overrides
  double voxels_per_radius = 0;  // > 0 overrides the scene's
  int threads = 0;               // as in effect, for the record
  bool quiet = false;
  bool no_correction = false;         // the plain Eq. 19 surface, whatever the scene says
  double contact_angle_deg = 0;       // > 0: alpha_base of every rigid
  bool check = false;                 // CGAL checks of every mesh, recorded in the sidecar
  bool level_set = false;             // also liquid.NNNN.vdb, whatever the scene says
  std::optional<std::string> preset;  // scene preset; unset: the one the manifest records
};

struct MeshFramesResult {
  int frames = 0;         // meshed
  int failed_checks = 0;  // with --check: frames whose mesh failed a check
};

// Meshes every selected frame. Everything checkable before meshing
// (manifest, scene, parameters, frame selection, particle files present) is
// checked before any output exists; a frame that fails later leaves earlier
// frames complete and nothing of its own. Throws std::runtime_error (or a
// subclass) whose message starts with the offending file.
MeshFramesResult mesh_frames(const MeshFramesOptions& options);

}  // namespace dp::mesh
