#include "mesh_sidecar.h"

#include "atomic_file.h"
#include "dewpoint/version.h"
#include "mesh_measures.h"

namespace dp::mesh {

namespace {

constexpr int kSidecarVersion = 2;

double degrees(double radians) { return radians * 180 / M_PI; }

nlohmann::json correction_json(const MeshSidecar& s, const LiquidSurface& surface) {
  nlohmann::json rigids = nlohmann::json::array();
  for (std::size_t r = 0; r < s.rigid_names.size(); ++r) {
    const DynamicContactAngleParameters& a = s.angles.per_rigid.at(r);
    rigids.push_back({{"name", s.rigid_names[r]},
                      {"mesh_file", s.rigid_files.at(r).string()},
                      {"contact_angle_deg", degrees(a.base)},
                      {"advancing_deg", degrees(a.advancing)},
                      {"receding_deg", degrees(a.receding)}});
  }
  const CorrectionCounts& c = surface.counts.correction;
  return {{"enabled", s.correction},
          {"reach_factor", s.angles.reach_factor},
          {"rigids", rigids},
          {"nodes_in_band", c.considered},
          {"nodes_corrected", c.corrected},
          {"wall_queries", c.wall_queries},
          {"blocks_near_walls", surface.counts.blocks_near_walls}};
}

}  // namespace

nlohmann::json mesh_sidecar_json(const MeshSidecar& s, const LiquidSurface& surface) {
  const GridBox& g = surface.grid;
  const double total =
      s.read_seconds + surface.field_seconds + surface.marching_cubes_seconds + s.check_seconds + s.write_seconds;
  nlohmann::json j = {
      {"format", "dewpoint-mesh-sidecar"},
      {"format_version", kSidecarVersion},
      {"generator", std::string("dewpoint-mesh ") + kVersion},
      {"frame", s.frame},
      {"time_s", s.time_s},
      {"source_frames_dir", s.frames_dir.string()},
      {"source_particles_file", s.particles_file},
      {"scene_file", s.scene_file.string()},
      {"mesh_file", s.mesh_file},
      {"level_set_file", s.level_set_file.empty() ? nlohmann::json() : nlohmann::json(s.level_set_file)},
      {"liquid_particles", s.liquid_particles},
      {"particle_radius_m", s.parameters.particle_radius},
      {"kernel_radius_m", s.parameters.kernel_radius},
      {"voxel_size_m", s.parameters.voxel_size},
      {"grid",
       {{"origin_m", {g.origin.x, g.origin.y, g.origin.z}},
        {"nodes", g.nodes},
        {"block_nodes", kFieldBlock},
        {"blocks", surface.counts.blocks},
        {"active_blocks", surface.counts.active_blocks}}},
      {"correction", correction_json(s, surface)},
      {"vertices", surface.mesh.position.size()},
      {"triangles", surface.mesh.triangles.size()},
      {"enclosed_volume_m3", enclosed_volume(surface.mesh)},
      {"surface_area_m2", surface_area(surface.mesh)},
      {"threads", s.threads},
      {"seconds", total},
      {"seconds_by_stage",
       {{"read", s.read_seconds},
        {"field", surface.field_seconds},
        {"marching_cubes", surface.marching_cubes_seconds},
        {"check", s.check_seconds},
        {"write", s.write_seconds}}},
      {"walls_setup_seconds", s.walls_seconds},
  };
  if (s.check) j["check"] = to_json(*s.check);
  return j;
}

void write_mesh_sidecar(const std::filesystem::path& file, const nlohmann::json& sidecar) {
  io::write_atomically(file, [&](std::ostream& out) { out << sidecar.dump(2) << "\n"; });
}

}  // namespace dp::mesh
