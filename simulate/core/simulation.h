#pragma once
// The simulator core's public face: a setup made of plain numbers (no files),
// a step, and snapshots of the state. Backends are hidden behind it.
#include <cstdint>
#include <memory>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "air/air_settings.h"
#include "air/air_state.h"
#include "backend/device.h"
#include "coupling/coupling_settings.h"
#include "coupling/water_ledger.h"
#include "math/vec3.h"
#include "simulation_state.h"
#include "sph/wall_shear_spalding1961.h"
#include "surface/surface_texture_setup.h"

namespace dp {

struct LiquidMaterial {
  float rest_density = 1000.0f;     // kg/m^3
  float conductivity = 0.6f;        // kappa, W/(m K), water
  float specific_heat = 4186.0f;    // C, J/(kg K), water
  float xsph_epsilon = 0.02f;       // XSPH viscosity between liquid particles
  float kinematic_viscosity = 0.0f; // nu, m^2/s (water 1e-6): Morris et al. 1997 (0: none)
  WallShear wall_shear = WallShear::NoSlip;  // how Morris's wall term shears the first layer
  float surface_tension = 0.0f;     // gamma of Akinci et al. 2013 (0: none)
  float boundary_friction = 0.02f;  // XSPH friction against rigid particles
  float temperature = 293.15f;      // K
};

// The rigid objects' material for heat conduction (one for all rigids).
struct RigidMaterial {
  float density = 2500.0f;         // kg/m^3 (glass)
  float conductivity = 1.0f;       // W/(m K)
  float specific_heat = 840.0f;    // J/(kg K)
};

// Which pressure solver: PCISPH as the paper (Solenthaler & Pajarola 2009),
// or divergence-free SPH (Bender & Koschier 2017, sph/dfsph_bender2017.h).
enum class PressureSolverMethod { Pcisph, Dfsph };

// The pressure solver and its stopping rule.
struct PressureSolverSettings {
  PressureSolverMethod method = PressureSolverMethod::Pcisph;
  float max_density_error = 0.005f;  // eta: average (rho* - rho0)/rho0
  float max_divergence_error = 0.001f;  // DFSPH's eta_v: average max(D rho/Dt, 0) dt / rho0
  int min_iterations = 3;
  int max_iterations = 100;
  // Start each solve from the last step's pressures instead of zero
  // (departure, docs/paper-map.md: SolveStart in sph/pcisph_solenthaler2009.h).
  bool warm_start = false;
};

// Settling before the first step (Simulation::settle): the liquid alone,
// its velocities damped, comes to rest against the rigids. Liquid blocks are
// lattices that stand off the walls and have no hydrostatic pressure yet; a
// deep column left to settle by itself pushes liquid into the gaps along
// the walls and shoots it up the corners at up to Torricelli's sqrt(2 g H).
struct SettleSettings {
  float duration = 0.0f;  // s of settling; 0: none
  float damping = 20.0f;  // 1/s: v -> v / (1 + damping dt) each step
};

enum class TimeStepMode { Fixed, Cfl };

struct TimeStepSettings {
  TimeStepMode mode = TimeStepMode::Cfl;
  float max_step = 2e-3f;       // s; the step in Fixed mode
  float min_step = 1e-6f;       // s; a CFL step below this is an instability
  float cfl_number = 0.4f;      // dt <= cfl * spacing / max speed
  float force_number = 0.25f;   // dt <= force * sqrt(spacing / max acceleration)
};

// What a liquid particle that leaves the domain's box does to the run.
enum class DomainLeaving {
  Stop,    // an instability: the run stops, naming the particle
  Remove,  // it leaves the shot, and its mass enters the water ledger's liquid_out
};

struct SimulationSetup {
  Vec3 domain_min, domain_max;  // m; see `leaving`
  DomainLeaving leaving = DomainLeaving::Stop;
  Vec3 gravity{0, -9.81f, 0};   // m/s^2
  float particle_spacing = 0.01f;  // m, rest spacing of liquid particles
  float max_speed = 50.0f;         // m/s; faster is an instability
  TimeStepSettings time_step;
  PressureSolverSettings pressure;
  SettleSettings settle;
  LiquidMaterial liquid;
  RigidMaterial rigid;
  bool heat_conduction = true;
  std::vector<Vec3> liquid_position, liquid_velocity;
  std::vector<float> liquid_temperature;  // K, per particle; empty: liquid.temperature
  std::vector<std::uint32_t> liquid_units;  // mass units (sph/mass_units.h) per particle; empty: full particles
  std::vector<Vec3> rigid_position;       // static boundary particles
  std::vector<float> rigid_temperature;   // K, per rigid particle
  std::vector<std::uint8_t> rigid_held;   // 1: held at its temperature (a heated plate)
  std::vector<float> rigid_adhesion;      // beta of Akinci et al. 2013 per rigid particle; empty: none
  std::vector<SurfaceTextureSetup> surfaces;  // textured rigids' static textures (paper Sec. 4.3)
  std::optional<AirSettings> air;         // the air phase (paper Sec. 4.2); none: particles only
  CouplingSettings coupling;              // heat and water between air, particles and textures (Sec. 5-6); needs `air`

  float support_radius() const { return 2.0f * particle_spacing; }
  float particle_mass() const {
    return liquid.rest_density * particle_spacing * particle_spacing * particle_spacing;
  }
};

// What one step did, for logs and the timing tables.
struct StepReport {
  float dt = 0;                 // s
  const char* limited_by = "";  // the rule that set dt (sph/time_step.h: step_limit_name); "convergence" also when halved
  int pressure_iterations = 0;  // PCISPH's, or DFSPH's density solve's
  int divergence_iterations = 0;  // DFSPH's divergence solve (0 with PCISPH)
  int pressure_halvings = 0;    // times PCISPH missed eta at its cap and the step was halved (CFL mode)
  float density_error = 0;      // average (rho* - rho0)/rho0 after the last iteration
  double seconds_neighbours = 0, seconds_pressure = 0, seconds_heat = 0, seconds_other = 0;  // wall clock
  double seconds_grid = 0;      // the air phase (Alg. 1 lines 7-11), wall clock
  double seconds_evaporation = 0;  // Alg. 1 lines 15-16 ("Eva" of the paper's Table 1), wall clock
  AirStepReport air;            // projection iterations and residual, sub-steps
  int particles_left_domain = 0;  // removed at the start of this step (DomainLeaving::Remove)
};

// The state of the liquid particles, in the core's current order; `id` is
// stable over the whole run.
struct ParticleSnapshot {
  std::vector<Vec3> position, velocity;
  std::vector<float> density, pressure, weight, temperature, surface_area;
  std::vector<std::uint32_t> mass_units;
  std::vector<std::uint32_t> id;
  std::size_t size() const { return position.size(); }
};

// A simulation that became unstable: which step, which quantity, where.
class InstabilityError : public std::runtime_error {
 public:
  InstabilityError(std::int64_t step, std::string quantity, std::uint32_t particle_id, Vec3 where,
                   const std::string& detail);
  // Of the air grid: `location` names the cell or face.
  InstabilityError(std::int64_t step, std::string quantity, const std::string& location);
  std::int64_t step;
  std::string quantity;
  std::uint32_t particle_id;
  Vec3 where;
};

class Simulation {
 public:
  virtual ~Simulation() = default;
  virtual StepReport step() = 0;  // throws InstabilityError
  // Steps until time() lands on `time` exactly, in equal steps no longer
  // than the time-step rule allows (never a sliver at the end); `on_step`,
  // when given, sees each step's report (for the per-step timing table).
  virtual void advance_to(double time, const std::function<void(const StepReport&)>& on_step = {}) = 0;
  // Settles the liquid as `SimulationSetup::settle` says, before the first
  // step (nothing otherwise, also after a restore); time() stays 0 and
  // step_count() 0; `on_step` sees each settling step.
  virtual void settle(const std::function<void(const StepReport&)>& on_step = {}) = 0;
  virtual ParticleSnapshot particles() const = 0;
  virtual std::vector<Vec3> rigid_particles() const = 0;
  virtual std::vector<float> rigid_volumes() const = 0;
  virtual std::vector<float> rigid_temperatures() const = 0;  // in the order of rigid_particles()
  virtual std::vector<SurfaceSnapshot> surfaces() const = 0;  // in the order of SimulationSetup::surfaces
  virtual std::int64_t step_count() const = 0;
  virtual double time() const = 0;  // s
  virtual std::string backend_name() const = 0;
  virtual const StepReport& last_step() const = 0;
  // The air grid's state; none when the setup has no air phase.
  virtual std::optional<AirSnapshot> air() const = 0;
  // Where the water is now, and the drift of its sum (coupling/water_ledger.h).
  virtual WaterLedger water_ledger() const = 0;
  // Everything that carries over to later steps (simulation_state.h), and
  // its restoration into a simulation made from the same setup; the run then
  // continues exactly as the one the state came from. restore throws
  // std::invalid_argument when the state does not fit this setup.
  virtual SimulationState state() const = 0;
  virtual void restore(const SimulationState& state) = 0;
};

// Throws std::runtime_error naming the reason when the device is unusable.
std::unique_ptr<Simulation> make_simulation(const ExecutionConfig& exec, const SimulationSetup& setup);

}  // namespace dp
