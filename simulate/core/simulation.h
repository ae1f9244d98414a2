#pragma once
// The simulator core's public face: a setup made of plain numbers (no files),
// a step, and snapshots of the state. Backends are hidden behind it.
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/device.h"
#include "math/vec3.h"

namespace dp {

struct LiquidMaterial {
  float rest_density = 1000.0f;     // kg/m^3
  float speed_of_sound = 20.0f;     // m/s, weakly compressible equation of state
  float viscosity_alpha = 0.02f;    // Monaghan artificial viscosity alpha
  float boundary_friction = 0.02f;  // the same viscosity against rigid particles (Akinci 2012)
  float temperature = 293.15f;      // K
};

struct SimulationSetup {
  Vec3 domain_min, domain_max;  // m; a particle leaving it is an instability
  Vec3 gravity{0, -9.81f, 0};   // m/s^2
  float particle_spacing = 0.01f;  // m, rest spacing of liquid particles
  float time_step = 1e-4f;         // s
  float max_speed = 50.0f;         // m/s; faster is an instability
  LiquidMaterial liquid;
  std::vector<Vec3> liquid_position, liquid_velocity;
  std::vector<Vec3> rigid_position;  // static boundary particles

  float support_radius() const { return 2.0f * particle_spacing; }
  float particle_mass() const {
    return liquid.rest_density * particle_spacing * particle_spacing * particle_spacing;
  }
};

// The state of the liquid particles, in the core's current order; `id` is
// stable over the whole run.
struct ParticleSnapshot {
  std::vector<Vec3> position, velocity;
  std::vector<float> density, pressure, weight, temperature;
  std::vector<std::uint32_t> id;
  std::size_t size() const { return position.size(); }
};

// A simulation that became unstable: which step, which quantity, where.
class InstabilityError : public std::runtime_error {
 public:
  InstabilityError(std::int64_t step, std::string quantity, std::uint32_t particle_id, Vec3 where,
                   const std::string& detail);
  std::int64_t step;
  std::string quantity;
  std::uint32_t particle_id;
  Vec3 where;
};

class Simulation {
 public:
  virtual ~Simulation() = default;
  virtual void step() = 0;  // throws InstabilityError
  virtual ParticleSnapshot particles() const = 0;
  virtual std::vector<Vec3> rigid_particles() const = 0;
  virtual std::vector<float> rigid_volumes() const = 0;
  virtual std::int64_t step_count() const = 0;
  virtual double time() const = 0;  // s
  virtual std::string backend_name() const = 0;
};

// Throws std::runtime_error naming the reason when the device is unusable.
std::unique_ptr<Simulation> make_simulation(const ExecutionConfig& exec, const SimulationSetup& setup);

// Largest stable time step for the setup's weakly compressible liquid
// (CFL number 0.4 on the smoothing length h/2 and the speed of sound).
float max_stable_time_step(const SimulationSetup& setup);

}  // namespace dp
