#pragma once
// The scene file's `render` section (docs/scene-format.md#render): camera,
// reconstruction filter, environment light, materials and output channels
// of dewpoint-render. Parsed and validated with the rest of the scene.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "json_reader.h"

namespace dp::io {

enum class MaterialType { Diffuse, Dielectric, Conductor };

struct Material {
  MaterialType type = MaterialType::Diffuse;
  std::array<double, 3> albedo{0.8, 0.8, 0.8};  // diffuse reflectance, or a conductor's tint (default 1)
  double ior = 1.33;                              // dielectric
  std::array<double, 3> absorption_per_m{0, 0, 0};  // Beer-Lambert inside a dielectric
  // A conductor's complex index of refraction eta + i k per RGB channel;
  // the defaults are aluminium (the usual mirror coating).
  std::array<double, 3> conductor_eta{1.65746, 0.880369, 0.521229};
  std::array<double, 3> conductor_k{9.22387, 6.26952, 4.837};
  // GGX alpha of the dry surface, of a texel holding its full m_t^max of
  // condensed water, and of a texel a drop has run over (wetting history 1).
  double roughness = 0;
  double fogged_roughness = 0;
  double wet_roughness = 0;
  double wet_darkening = 0;  // a wet texel reflects (1 - this) as much
  std::array<double, 3> emission{0, 0, 0};  // radiance emitted from the front side (W/(m^2 sr) per channel)
};

enum class CameraModel { Pinhole, ThinLens };

struct CameraSettings {
  CameraModel model = CameraModel::Pinhole;
  std::array<double, 3> position_m{0, 1, 2};
  std::array<double, 3> look_at_m{0, 0, 0};
  std::array<double, 3> up{0, 1, 0};
  double fov_deg = 40;
  double aperture_radius_m = 0;  // thin lens
  double focus_distance_m = 0;   // thin lens; 0: the distance to look_at_m
};

enum class FilterType { Box, Tent, Gaussian };

struct FilterSettings {
  FilterType type = FilterType::Gaussian;
  double radius_px = 1.5;
  double sigma_px = 0.5;  // Gaussian
};

enum class EnvironmentType { Sky, Constant, Map };

struct EnvironmentSettings {
  EnvironmentType type = EnvironmentType::Sky;
  std::array<double, 3> zenith{0.55, 0.7, 1.0};  // sky colour overhead
  std::array<double, 3> horizon{1.0, 1.0, 1.0};  // at the horizon
  std::array<double, 3> ground{0.25, 0.22, 0.2};
  std::array<double, 3> radiance{1, 1, 1};        // constant
  std::filesystem::path map;                       // lat-long EXR, resolved against the scene file's folder
  double rotation_deg = 0;                         // map turned about +y
  double intensity = 1.0;
};

// How a pixel's samples are placed: independently, or as an Owen-scrambled
// Sobol sequence (stratified, lower error at equal spp).
enum class SamplerType { Independent, Sobol };

struct AovSelection {
  bool albedo = true, normal = true, depth = true;
};

struct RenderSettings {
  int width = 480, height = 270;
  int spp = 32;
  int max_depth = 12;
  std::uint64_t seed = 1;
  SamplerType sampler = SamplerType::Sobol;
  double exposure_stops = 0;
  CameraSettings camera;
  FilterSettings filter;
  EnvironmentSettings environment;
  AovSelection aovs;
  bool wet_paths = true;  // the wetting history changes the look of rigids
  std::string liquid_material = "water";
  std::map<std::string, Material> materials;          // by name
  std::map<std::string, std::string> rigid_material;  // rigid name -> material name
};

// "albedo,normal,depth", any subset, or "none"; throws std::invalid_argument
// naming the unknown entry.
AovSelection parse_aov_list(const std::string& text);

// Reads and validates `render`; rigid_names are simulation.rigids' names,
// each of which needs an entry in render.objects.
RenderSettings read_render_settings(JsonObject render, const std::vector<std::string>& rigid_names,
                                    const std::filesystem::path& scene_dir);

}  // namespace dp::io
