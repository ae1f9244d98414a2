#pragma once
// dewpoint-mesh's work: every selected frame of a frames folder to a liquid
// mesh and its sidecar in the output folder.
#include <filesystem>

#include "cli_common.h"

namespace dp::mesh {

struct MeshFramesOptions {
  std::filesystem::path frames_dir, out_dir;
  io::FrameRange range;
  double voxel_size = 0;         // > 0 overrides
  double voxels_per_radius = 0;  // > 0 overrides the scene's
  int threads = 0;               // as in effect, for the record
  bool quiet = false;
};

// Returns how many frames were meshed. Everything checkable before meshing
// (manifest, scene, parameters, frame selection, particle files present) is
// checked before any output exists; a frame that fails later leaves earlier
// frames complete and nothing of its own. Throws std::runtime_error (or a
// subclass) whose message starts with the offending file.
int mesh_frames(const MeshFramesOptions& options);

}  // namespace dp::mesh
