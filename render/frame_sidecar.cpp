#include "frame_sidecar.h"

#include "atomic_file.h"
#include "dewpoint/version.h"

namespace dp::render {

nlohmann::json sidecar_json(const FrameRecord& r) {
  const double samples = static_cast<double>(r.width) * r.height * r.spp;
  nlohmann::json textures = nlohmann::json::array();
  for (const auto& t : r.surface_textures) textures.push_back(t.string());
  return {{"generator", std::string("dewpoint-render ") + dp::kVersion},
          {"scene_file", r.scene_file.string()},
          {"liquid_mesh", r.liquid_mesh.string()},
          {"frame", r.frame},
          {"frame_time_s", r.frame_time_s},
          {"resolution", {r.width, r.height}},
          {"spp", r.spp},
          {"max_depth", r.max_depth},
          {"seed", r.seed},
          {"exposure_stops", r.exposure_stops},
          {"threads", r.threads},
          {"render_time_s", r.render_time_s},
          {"samples_per_s", r.render_time_s > 0 ? samples / r.render_time_s : 0.0},
          {"sampler", r.sampler},
          {"camera", r.camera},
          {"filter", r.filter},
          {"environment", r.environment},
          {"aovs", r.aovs},
          {"wet_paths", r.wet_paths},
          {"area_light_triangles", r.area_light_triangles},
          {"surface_textures", textures},
          {"integrator", "unidirectional path tracing, next-event estimation with MIS (power heuristic), Russian roulette"}};
}

void write_sidecar(const std::filesystem::path& file, const FrameRecord& record) {
  dp::io::write_atomically(file, [&](std::ostream& out) { out << sidecar_json(record).dump(2) << "\n"; });
}

}  // namespace dp::render
