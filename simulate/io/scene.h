#pragma once
// A shot, as the scene file describes it for all three stages
// (docs/scene-format.md). Loading validates everything before any work.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_reader.h"
#include "coupling/evaporation_rate_smith1994.h"
#include "render_settings.h"

namespace dp::io {

using Vec3d = std::array<double, 3>;
using Rgb = std::array<double, 3>;

inline constexpr double kZeroCelsiusInKelvin = 273.15;  // the one place Celsius meets kelvin
inline double celsius_to_kelvin(double c) { return c + kZeroCelsiusInKelvin; }

// A region filled with liquid particles on a cubic lattice: a box, or the
// lattice points of the bounding box [min_m, max_m] that lie inside a sphere
// or an upright (y-axis) cylinder (a drop, a glass's content).
enum class LiquidShape { Box, Sphere, Cylinder };

struct LiquidBlock {
  LiquidShape shape = LiquidShape::Box;
  Vec3d min_m, max_m;
  Vec3d center_m{0, 0, 0};  // sphere: centre; cylinder: centre of its base
  double radius_m = 0, height_m = 0;
  Vec3d velocity_m_s{0, 0, 0};
};

// A rigid's surface textures (paper Sec. 4.3; docs/scene-format.md).
struct TextureSettings {
  int width = 0, height = 0;                 // texels
  double max_mass_kg_m2 = 0.05;              // m_t^max per area when no image is given
  std::filesystem::path max_mass_image;      // empty: the constant above
  double max_mass_image_scale_kg_m2 = 0.05;  // kg/m^2 at image value 1
  double initial_mass_kg_m2 = 0;             // clamped to m_t^max per texel
  double wetting_decay_s = 1;                // time for the wetting history to fall by 1/e
};

struct RigidObject {
  std::string name;
  std::filesystem::path mesh;  // resolved against the scene file's folder
  double temperature_k = 293.15;
  bool hold_temperature = false;  // held at temperature_k (a heated plate, a cooled mirror)
  double adhesion = 0;            // beta of Akinci et al. 2013
  std::optional<TextureSettings> texture;  // none: the rigid has no surface textures
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
  double kinematic_viscosity_m2_s = 1.0e-6;  // water at 20 C (Morris et al. 1997)
  double surface_tension = 0;  // gamma of Akinci et al. 2013
  double boundary_friction = 0.02;  // XSPH wall friction: a per-step knob
  std::string wall_shear = "spalding1961";  // the law of the wall, or "no_slip"
  double temperature_k = 293.15;
};

struct PressureSolverSettings {
  std::string method = "pcisph";  // or "dfsph"
  double max_density_error = 0.005;
  double max_divergence_error = 0.001;
  int min_iterations = 3;
  int max_iterations = 100;
  bool warm_start = false;
};

// simulation.settle: the liquid comes to rest before t = 0.
struct SettleSectionSettings {
  double duration_s = 0;
  double damping_per_s = 20;
};

// simulation.air (paper Sec. 4.2); see docs/scene-format.md.
struct AirInflowSettings {
  bool disc = false;
  Vec3d min_m{0, 0, 0}, max_m{0, 0, 0};             // box
  Vec3d center_m{0, 0, 0}, normal{0, 1, 0};         // disc
  double radius_m = 0, thickness_m = 0;             // disc; thickness 0: one air cell
  Vec3d velocity_m_s{0, 0, 0};
  double temperature_k = 293.15;
  double vapor_kg_m3 = 0;
};

// `simulation.coupling`: heat and water between air, particles and
// textures (paper Sec. 5-6); defaults in simulate/core/coupling/.
struct CouplingSectionSettings {
  double evaporation_a = EvaporationCoefficients{}.a;  // kg/(m^2 s Pa), Eq. 12's a
  double evaporation_b = EvaporationCoefficients{}.b;  // kg/(m^3 Pa), Eq. 12's b
  double phase_change_time_scale = 1.0;               // CouplingSettings::phase_change_time_scale
  bool heat_exchange = true, particle_evaporation = true, texel_exchange = true, particle_emission = true;
  bool latent_heat = false;
  double latent_heat_j_kg = 2.26e6;
  bool path_force = false;
  double path_adhesion = 10.0;
  double air_density_kg_m3 = 1.204, air_specific_heat_j_kgk = 1005, air_conductivity_w_mk = 0.0257;
};

struct AirSectionSettings {
  int resolution = 64;
  Vec3d domain_min_m, domain_max_m;  // default: the simulation domain
  double temperature_k = 293.15;
  double vapor_kg_m3 = 0;
  double buoyancy_alpha = -3.09;
  double buoyancy_beta = 0.0335;
  double vorticity_epsilon = 0;
  double vapor_diffusivity_m2_s = 2.5e-5;
  double heat_diffusivity_m2_s = 2.2e-5;
  bool maccormack = false;
  std::array<bool, 6> open_face{};  // x_min, x_max, y_min, y_max, z_min, z_max
  std::vector<AirInflowSettings> inflows;
  double projection_tolerance = 1e-5;
  int projection_max_iterations = 200;
};

struct SimulationSettings {
  Vec3d domain_min_m, domain_max_m;
  std::string domain_leaving = "stop";  // or "remove": a particle past the box leaves the shot
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
  SettleSectionSettings settle;
  std::vector<LiquidBlock> liquid_blocks;
  std::vector<RigidObject> rigids;
  RigidMaterialSettings rigid_material;
  std::optional<AirSectionSettings> air;
  CouplingSectionSettings coupling;
};

struct MeshSettings {
  double voxels_per_radius = 2;   // voxel size = particle radius / this
  double kernel_radius_factor = 2;  // Zhu-Bridson kernel radius R = factor * particle spacing
  double particle_radius_factor = 0.5;  // r_i = factor * particle spacing
  // Contact-angle corrections of paper Sec. 7 (Eq. 20-24).
  bool correction = true;
  double contact_angle_deg = 90;                           // static alpha_base of any rigid not listed below
  std::map<std::string, double> rigid_contact_angle_deg;  // rigid name -> its alpha_base
  double advancing_deg = 20;  // A_adv of Eq. 22, degrees per (m/s)^(1/3)
  double receding_deg = 20;   // A_rec of Eq. 22, degrees per (m/s)^(1/3)
  double correction_reach_factor = 1;  // correct where |xbar - xbar_p| < factor * rbar (the paper: 1)
  bool level_set = false;  // also write the meshed field as an OpenVDB level set (dewpoint-mesh --level-set)
};

struct Scene {
  std::filesystem::path file;  // absolute
  std::string name;
  std::string preset;       // the preset applied (docs/scene-format.md, "Presets"); empty: none
  nlohmann::json document;  // as run: with the preset applied and `presets` removed; recorded in outputs
  SimulationSettings simulation;
  MeshSettings mesh;
  RenderSettings render;
};

// Parses, applies the preset named `preset` (none when empty) and
// validates; throws SceneError naming file, key, expected and found.
Scene load_scene(const std::filesystem::path& file, const std::string& preset = "");

}  // namespace dp::io
