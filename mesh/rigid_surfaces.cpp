#include "rigid_surfaces.h"

#include <cmath>
#include <stdexcept>

namespace dp::mesh {

namespace fs = std::filesystem;

namespace {

double radians(double degrees) { return degrees * M_PI / 180; }

// The manifest's rigids[] entry naming `name`'s mesh in the frames folder, if any.
fs::path frames_folder_mesh(const io::FramesManifest& manifest, const fs::path& frames_dir, const std::string& name) {
  const nlohmann::json& j = manifest.extra;
  if (!j.contains("rigids") || !j["rigids"].is_array()) return {};
  for (const nlohmann::json& r : j["rigids"]) {
    if (!r.is_object() || !r.contains("name") || r["name"] != name) continue;
    if (!r.contains("mesh") || !r["mesh"].is_string())
      throw std::runtime_error((frames_dir / "manifest.json").string() + ": rigids entry '" + name +
                               "': mesh: expected a file name");
    return frames_dir / r["mesh"].get<std::string>();
  }
  return {};
}

}  // namespace

RigidSurfaces load_rigid_surfaces(const io::Scene& scene, const io::FramesManifest& manifest, const fs::path& frames_dir) {
  RigidSurfaces s;
  for (const io::RigidObject& rigid : scene.simulation.rigids) {
    fs::path file = frames_folder_mesh(manifest, frames_dir, rigid.name);
    if (file.empty()) file = rigid.mesh;
    s.names.push_back(rigid.name);
    s.files.push_back(file);
    s.meshes.push_back(io::load_triangle_mesh(file));  // its errors name the file
  }
  return s;
}

ContactAngleSettings contact_angle_settings(const io::MeshSettings& settings, const std::vector<std::string>& rigid_names,
                                            double contact_angle_override_deg) {
  ContactAngleSettings c;
  c.reach_factor = settings.correction_reach_factor;
  for (const std::string& name : rigid_names) {
    DynamicContactAngleParameters p;
    double base = settings.contact_angle_deg;
    if (auto it = settings.rigid_contact_angle_deg.find(name); it != settings.rigid_contact_angle_deg.end()) base = it->second;
    if (contact_angle_override_deg > 0) base = contact_angle_override_deg;
    p.base = radians(base);
    p.advancing = radians(settings.advancing_deg);
    p.receding = radians(settings.receding_deg);
    c.per_rigid.push_back(p);
  }
  return c;
}

}  // namespace dp::mesh
