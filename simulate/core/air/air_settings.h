#pragma once
// The air phase's settings as plain numbers (paper Sec. 4.2); the scene's
// `simulation.air` section (docs/scene-format.md) is read into this by
// simulate/io. Temperatures in kelvin, vapor as density in kg/m^3.
#include <array>
#include <optional>
#include <vector>

#include "air/cycle_layout.h"
#include "math/vec3.h"

namespace dp {

enum class AirAdvection { SemiLagrangian, MacCormack };

// A region where velocity, temperature and vapor density are prescribed
// every step (the paper blows humid air onto the mirror and the glass).
struct AirInflow {
  enum class Shape { Box, Disc } shape = Shape::Box;
  Vec3 box_min, box_max;         // Box
  Vec3 center, normal{0, 1, 0};  // Disc: a cylinder of `thickness` along the unit normal
  float radius = 0, thickness = 0;
  Vec3 velocity;                // m/s
  float temperature = 293.15f;  // K
  double vapor = 0;             // kg/m^3
};

// Faces of the domain, in the order x-, x+, y-, y+, z-, z+.
enum class AirFace { XMin, XMax, YMin, YMax, ZMin, ZMax };

struct AirSettings {
  Vec3 domain_min, domain_max;  // covered by whole cubic cells; see air_grid_layout()
  int resolution = 64;          // cells along the longest axis of the domain
  float ambient_temperature = 293.15f;  // K: T_amb of Eq. 5 and the initial air
  double ambient_vapor = 0;             // kg/m^3: initial vapor and what open faces let in
  // Eq. 5: f = alpha rho_v (-up) + beta (T - T_amb) up; see buoyancy_fedkiw2001.h.
  float buoyancy_alpha = -3.09f;   // m^4/(kg s^2); < 0: humid air rises
  float buoyancy_beta = 0.0335f;   // m/(s^2 K): |g| / T_amb
  float vorticity_epsilon = 0;     // 1/s, Fedkiw et al. 2001
  float vapor_diffusivity = 2.5e-5f;  // m^2/s, water vapor in air
  float heat_diffusivity = 2.2e-5f;   // m^2/s, air
  AirAdvection advection = AirAdvection::SemiLagrangian;
  std::vector<AirInflow> inflows;
  std::array<bool, 6> open_face{};  // per AirFace; false: closed wall
  float projection_tolerance = 1e-5f;  // |r|_2 / |b|_2 of the pressure solve
  int projection_max_iterations = 200;
  // Times each part of the step (AirStepReport::seconds); on the GPU this
  // waits for the device after every part, so it is for benchmarks.
  bool time_parts = false;
  // The pressure V-cycle's layout over launches; unset: the backend's own.
  // Every layout computes the same; for benchmarks that compare them on one
  // GPU (dewpoint-bench-air --cycle-layout).
  std::optional<CycleLayout> cycle_layout;
};

}  // namespace dp
