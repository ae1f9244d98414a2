#pragma once
// Predictive-corrective incompressible SPH, Solenthaler & Pajarola 2009
// (paper Alg. 1 line 6). Pressures are corrected iteratively from the
// density error of predicted positions until the average error is below eta.
// Rigid particles contribute density and push back as in Akinci et al. 2012.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/density.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/listed_particles.h"
#include "sph/mass_units.h"
#include "sph/neighbor_list.h"
#include "sph/uniform_grid.h"

namespace dp {

// The neighbourhood sum of Solenthaler & Pajarola's Eq. 8 for a particle
// with a filled neighbourhood (a cubic lattice at the rest spacing):
// S = |sum_j gradW_ij|^2 + sum_j |gradW_ij|^2; then
// delta(dt) = 1 / (2 (dt m / rho0)^2 S). Computed once on the host.
float pcisph_prototype_sum(const CubicSplineKernel& kernel, float spacing);

DP_HD inline float pcisph_delta(float prototype_sum, float dt, float particle_mass, float rest_density) {
  float beta = 2.0f * (dt * particle_mass / rest_density) * (dt * particle_mass / rest_density);
  return 1.0f / (beta * prototype_sum);
}

// x* = x + dt v*,  v* = v + dt (a_nonpressure + a_pressure).
struct PredictPosition {
  const Vec3* position;
  const Vec3* velocity;
  const Vec3* nonpressure_acceleration;
  const Vec3* pressure_acceleration;
  float dt;
  Vec3* predicted;
  DP_HD void operator()(std::size_t i) const {
    Vec3 v = velocity[i] + dt * (nonpressure_acceleration[i] + pressure_acceleration[i]);
    predicted[i] = position[i] + dt * v;
  }
};

// Where a solve starts. Solenthaler & Pajarola start every step from zero
// pressure, so every step builds the liquid's whole hydrostatic pressure
// again: a column some 60 particles deep (the glass) then needs 25-45
// iterations a step at eta = 0.5 %. Warm, a step starts from a share of the
// last step's pressures, as IISPH does (Ihmsen et al. 2014, "Implicit
// Incompressible SPH", Sec. 3.3: half of them). Pressures here only grow
// within a solve (CorrectPressure), so a start that is too high could only
// relax over the following steps: at half, an excess halves every step (a
// share of 0.8 or more let it build up until the glass's liquid blew up
// while settling). Departure, docs/paper-map.md.
enum class SolveStart { Cold, Warm };
inline constexpr float kWarmStartShare = 0.5f;

// p_i = share * (the last step's p_i), from which a warm solve's first
// prediction starts.
struct StartPressure {
  float share;
  const float* last;
  float* pressure;
  DP_HD void operator()(std::size_t i) const { pressure[i] = share * last[i]; }
};

// The density at the predicted positions, over the neighbours listed at the
// start of the step (as Solenthaler & Pajarola keep the step's
// neighbourhoods), clamped from below at rho0 so that the free surface does
// not pull: p_i += delta * (rho*_i - rho0); the error is kept for the
// average.
struct CorrectPressure {
  ListedDensity predicted_density;  // over the predicted positions
  float delta;
  float* pressure;
  float* density_error;  // (rho* - rho0)/rho0, >= 0
  DP_HD void operator()(std::size_t i) const { correct(i, predicted_density(i)); }
  // The CPU's: the same densities by ListedDensity::split_sum.
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    for (std::size_t i = begin; i < end; ++i) correct(i, predicted_density.split_sum(i));
  }
  DP_HD void correct(std::size_t i, float rho) const {
    const float rho0 = predicted_density.rest_density;
    float error = rho > rho0 ? rho - rho0 : 0.0f;
    pressure[i] += delta * error;
    density_error[i] = error / rho0;
  }
};

// a_i = -sum_j m_j (p_i + p_j)/rho0^2 gradW_ij - sum_b Psi_b p_i/rho0^2 gradW_ib
// at the positions of the step's start (Solenthaler & Pajarola use rho0 in
// the denominators; Akinci 2012 Eq. 10 for the boundary), with the pairs'
// gradient factors the step's lists keep (FillNeighbors).
struct ComputePressureAcceleration {
  ListedParticles p;
  const float* pressure;
  Vec3* acceleration;
  DP_HD void operator()(std::size_t i) const {
    const float inv_rho2 = 1.0f / (p.rest_density * p.rest_density);
    const float pi = pressure[i];
    Vec3 a{};
    const NeighborList& liquid = p.liquid_pairs.list;
    for (std::uint32_t k = liquid.offset[i]; k < liquid.offset[i + 1]; ++k) {
      const std::uint32_t j = liquid.index[k];
      if (j == i) continue;
      a -= (p.mass(j) * (pi + pressure[j]) * inv_rho2) * p.liquid_gradient(i, k);
    }
    const NeighborList& rigid = p.rigid_pairs.list;
    for (std::uint32_t k = rigid.offset[i]; k < rigid.offset[i + 1]; ++k)
      a -= (p.rest_density * p.rigid_volume[rigid.index[k]] * pi * inv_rho2) * p.rigid_gradient(i, k);
    acceleration[i] = a;
  }
};

struct ClearPressure {
  float* pressure;
  Vec3* acceleration;
  DP_HD void operator()(std::size_t i) const {
    pressure[i] = 0.0f;
    acceleration[i] = Vec3{};
  }
};

// Symplectic Euler with the total acceleration.
struct IntegrateMotion {
  const Vec3* nonpressure_acceleration;
  const Vec3* pressure_acceleration;
  float dt;
  Vec3* velocity;
  Vec3* position;
  DP_HD void operator()(std::size_t i) const {
    velocity[i] += dt * (nonpressure_acceleration[i] + pressure_acceleration[i]);
    position[i] += dt * velocity[i];
  }
};

}  // namespace dp
