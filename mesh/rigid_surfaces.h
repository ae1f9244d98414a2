#pragma once
// The rigid geometry a frames folder was simulated with, and the contact
// angles the scene gives each rigid (docs/scene-format.md, section mesh).
#include <filesystem>
#include <string>
#include <vector>

#include "contact_angle_correction.h"
#include "frames.h"
#include "scene.h"
#include "triangle_mesh.h"

namespace dp::mesh {

struct RigidSurfaces {
  std::vector<std::string> names;               // the scene's rigids[].name, in scene order
  std::vector<std::filesystem::path> files;     // where each mesh was read from
  std::vector<io::TriangleMesh> meshes;         // world space
};

// Each rigid's world-space mesh: the frames folder's rigid_NAME.ply when the
// manifest lists one (the geometry the simulator used, with its atlas),
// otherwise the scene's rigids[].mesh. Throws naming the file that fails.
RigidSurfaces load_rigid_surfaces(const io::Scene& scene, const io::FramesManifest& manifest,
                                  const std::filesystem::path& frames_dir);

// Per rigid: alpha_base from contact_angle_override_deg when > 0, else the
// scene's mesh.rigids.NAME.contact_angle_deg, else mesh.contact_angle_deg;
// A_adv and A_rec from the scene.
ContactAngleSettings contact_angle_settings(const io::MeshSettings& settings, const std::vector<std::string>& rigid_names,
                                            double contact_angle_override_deg = 0);

}  // namespace dp::mesh
