#pragma once
// beauty.NNNN.json, written next to each frame's images: how the frame was
// made and how long it took, for reproducing it and for tracking speed.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dp::render {

struct FrameRecord {
  std::filesystem::path scene_file;
  std::filesystem::path liquid_mesh;
  int frame = 0;
  double frame_time_s = 0;  // simulated time of the frame
  int width = 0, height = 0;
  int spp = 0;
  int max_depth = 0;
  std::uint64_t seed = 0;
  double exposure_stops = 0;
  int threads = 0;  // 0: all cores
  double render_time_s = 0;  // wall-clock, image only (no file I/O)
  std::string sampler;       // sobol or independent
  std::string camera;        // pinhole or thin_lens
  std::string filter;        // box, tent or gaussian
  std::string environment;   // sky, constant or map
  std::string aovs;          // the EXR's auxiliary channels
  bool wet_paths = true;
  std::size_t area_light_triangles = 0;
  std::vector<std::filesystem::path> surface_textures;  // rigid textures used for this frame
};

nlohmann::json sidecar_json(const FrameRecord& record);
void write_sidecar(const std::filesystem::path& file, const FrameRecord& record);

}  // namespace dp::render
