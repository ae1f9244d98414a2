#pragma once
// A shot, as the scene file describes it for all three stages
// (docs/scene-format.md). Loading validates everything before any work.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_reader.h"
#include "render_settings.h"

namespace dp::io {

using Vec3d = std::array<double, 3>;
using Rgb = std::array<double, 3>;

inline constexpr double kZeroCelsiusInKelvin = 273.15;  // the one place Celsius meets kelvin
inline double celsius_to_kelvin(double c) { return c + kZeroCelsiusInKelvin; }

struct LiquidBlock {
  Vec3d min_m, max_m;
  Vec3d velocity_m_s{0, 0, 0};
};

struct RigidObject {
  std::string name;
  std::filesystem::path mesh;  // resolved against the scene file's folder
  double temperature_k = 293.15;
  bool hold_temperature = false;  // held at temperature_k (a heated plate, a cooled mirror)
  double adhesion = 0;            // beta of Akinci et al. 2013
};

struct RigidMaterialSettings {
  double density_kg_m3 = 2500;
  double conductivity_w_mk = 1.0;
  double specific_heat_j_kgk = 840;
};

struct LiquidSettings {
  double rest_density_kg_m3 = 1000;
  double conductivity_w_mk = 0.6;
  double specific_heat_j_kgk = 4186;
  double xsph_epsilon = 0.02;
  double surface_tension = 0;  // gamma of Akinci et al. 2013
  double boundary_friction = 0.02;
  double temperature_k = 293.15;
};

struct PressureSolverSettings {
  double max_density_error = 0.005;
  int min_iterations = 3;
  int max_iterations = 100;
};

struct SimulationSettings {
  Vec3d domain_min_m, domain_max_m;
  Vec3d gravity_m_s2{0, -9.81, 0};
  double particle_spacing_m = 0.01;
  double time_step_s = 2e-3;  // the step (fixed) or its upper bound (cfl)
  bool cfl_time_step = true;
  double cfl_number = 0.4;
  double duration_s = 1;
  double frame_rate_hz = 24;
  double max_speed_m_s = 50;
  LiquidSettings liquid;
  PressureSolverSettings pressure_solver;
  std::vector<LiquidBlock> liquid_blocks;
  std::vector<RigidObject> rigids;
  RigidMaterialSettings rigid_material;
};

struct MeshSettings {
  double voxels_per_radius = 2;   // voxel size = particle radius / this
  double kernel_radius_factor = 2;  // Zhu-Bridson kernel radius R = factor * particle spacing
  double particle_radius_factor = 0.5;  // r_i = factor * particle spacing
};

struct Scene {
  std::filesystem::path file;  // absolute
  std::string name;
  nlohmann::json document;  // as read, recorded in outputs
  SimulationSettings simulation;
  MeshSettings mesh;
  RenderSettings render;
};

// Parses and validates; throws SceneError naming file, key, expected and found.
Scene load_scene(const std::filesystem::path& file);

}  // namespace dp::io
