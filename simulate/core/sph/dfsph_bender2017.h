#pragma once
// Divergence-free SPH, Bender & Koschier 2017 ("Divergence-Free SPH for
// Incompressible and Viscous Fluids", IEEE TVCG 23(3); first as SCA 2015):
// a second pressure solver beside PCISPH (pressure_solver.method "dfsph").
// Two Jacobi solvers share one factor per particle and one velocity
// correction:
//  * the divergence solve (their Alg. 2) makes the velocity field
//    divergence-free at the start of the step, so particles stop moving
//    into one another before the step, not by a pressure jolt within it;
//  * the density solve (their Alg. 3) removes the density error the
//    predicted velocities would leave at the end of the step.
// Both predict densities from velocities over the step's neighbour lists,
// so an iteration needs no position prediction and no new neighbours.
// Rigid particles contribute as Akinci et al. 2012 boundaries (volume V_b,
// Psi_b = rho0 V_b, at rest), pressure mirrored (p_b = p_i), as Bender &
// Koschier do with such boundaries.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/listed_particles.h"

namespace dp {

// Both solves are Jacobi iterations that correct each particle as if its
// neighbours' own corrections were not coming. Bender & Koschier apply the
// full correction; we apply half, as IISPH relaxes its Jacobi solve
// (Ihmsen et al. 2014, omega = 0.5). In a settled column 60 layers deep at
// 2 ms steps the full correction overshoots and keeps the liquid jittering
// (mean speed 2-8 cm/s, peaks 0.6 m/s in the corners); at half it is as
// still as PCISPH's (mean 0.5 cm/s) in as many iterations. Departure,
// docs/paper-map.md.
inline constexpr float kDfsphRelaxation = 0.5f;

// Their Eq. 11, the boundary in the first sum:
// alpha_i = rho_i / (|sum_j m_j gradW_ij + sum_b Psi_b gradW_ib|^2 + sum_j |m_j gradW_ij|^2).
// A stiffness kappa_i = (rate of density error) alpha_i then removes that
// error, when i's neighbours are corrected along with it.
struct ComputeDfsphFactor {
  ListedParticles p;
  float* factor;
  DP_HD void operator()(std::size_t i) const {
    Vec3 sum{};
    float sum_of_squares = 0.0f;
    const NeighborList& liquid = p.liquid_pairs.list;
    for (std::uint32_t k = liquid.offset[i]; k < liquid.offset[i + 1]; ++k) {
      const std::uint32_t j = liquid.index[k];
      if (j == i) continue;
      const Vec3 term = p.mass(j) * p.liquid_gradient(i, k);
      sum += term;
      sum_of_squares += length_squared(term);
    }
    const NeighborList& rigid = p.rigid_pairs.list;
    for (std::uint32_t k = rigid.offset[i]; k < rigid.offset[i + 1]; ++k)
      sum += (p.rest_density * p.rigid_volume[rigid.index[k]]) * p.rigid_gradient(i, k);
    const float denominator = length_squared(sum) + sum_of_squares;
    // A particle alone has no neighbour to push against.
    factor[i] = denominator > 1e-20f ? p.density[i] / denominator : 0.0f;
  }
};

// D rho_i / Dt = sum_j m_j (v_i - v_j) . gradW_ij + sum_b Psi_b v_i . gradW_ib
// (their Eq. 9; rigid particles at rest).
DP_HD inline float density_change_rate(const ListedParticles& p, const Vec3* velocity, std::size_t i) {
  const Vec3 vi = velocity[i];
  float rate = 0.0f;
  const NeighborList& liquid = p.liquid_pairs.list;
  for (std::uint32_t k = liquid.offset[i]; k < liquid.offset[i + 1]; ++k) {
    const std::uint32_t j = liquid.index[k];
    if (j == i) continue;
    rate += p.mass(j) * dot(vi - velocity[j], p.liquid_gradient(i, k));
  }
  const NeighborList& rigid = p.rigid_pairs.list;
  for (std::uint32_t k = rigid.offset[i]; k < rigid.offset[i + 1]; ++k)
    rate += (p.rest_density * p.rigid_volume[rigid.index[k]]) * dot(vi, p.rigid_gradient(i, k));
  return rate;
}

// The divergence solve's stiffness: kappa^v_i = omega max(D rho_i/Dt, 0) alpha_i / dt
// (their Eq. 12, relaxed). Only compression is removed: liquid that
// separates at a free surface is left to separate. The error is
// (D rho_i/Dt) dt / rho0.
struct ComputeDivergenceStiffness {
  ListedParticles p;
  const Vec3* velocity;
  const float* factor;
  float dt;
  float relaxation;
  float* stiffness;
  float* error;
  DP_HD void operator()(std::size_t i) const {
    float rate = density_change_rate(p, velocity, i);
    rate = rate > 0.0f ? rate : 0.0f;
    stiffness[i] = relaxation * rate * factor[i] / dt;
    error[i] = rate * dt / p.rest_density;
  }
};

// The density solve's stiffness from the predicted velocities v* =
// v + dt (a_nonpressure + a_pressure): rho*_i = rho_i + dt D rho_i/Dt(v*),
// kappa_i = omega max(rho*_i - rho0, 0) alpha_i / dt^2 (their Eq. 6-7, 11,
// relaxed; a free surface does not pull).
struct ComputeDensityStiffness {
  ListedParticles p;
  const Vec3* predicted_velocity;  // filled by PredictVelocity for this iteration
  const float* factor;
  float dt;
  float relaxation;
  float* stiffness;
  float* error;  // (rho* - rho0)/rho0, >= 0
  DP_HD void operator()(std::size_t i) const {
    const float predicted = p.density[i] + dt * density_change_rate(p, predicted_velocity, i);
    const float excess = predicted > p.rest_density ? predicted - p.rest_density : 0.0f;
    stiffness[i] = relaxation * excess * factor[i] / (dt * dt);
    error[i] = excess / p.rest_density;
  }
};

// v*_i = v_i + dt (a_nonpressure + a_pressure).
struct PredictVelocity {
  const Vec3* velocity;
  const Vec3* nonpressure_acceleration;
  const Vec3* pressure_acceleration;
  float dt;
  Vec3* predicted_velocity;
  DP_HD void operator()(std::size_t i) const {
    predicted_velocity[i] = velocity[i] + dt * (nonpressure_acceleration[i] + pressure_acceleration[i]);
  }
};

// The correction of the stiffnesses: target_i += scale a_i with
// a_i = -sum_j m_j (kappa_i/rho_i + kappa_j/rho_j) gradW_ij
//       - sum_b Psi_b (kappa_i/rho_i) gradW_ib      (their Eq. 13, 8).
// The density solve adds a_i to the pressure acceleration (scale 1), the
// divergence solve dt a_i to the velocity (scale dt); each adds kappa_i rho_i
// to its pressure (Pa), of which the step's is the sum (the frames write it).
struct AddStiffnessCorrection {
  ListedParticles p;
  const float* stiffness;
  float scale;
  Vec3* target;
  float* pressure = nullptr;
  DP_HD void operator()(std::size_t i) const {
    if (pressure) pressure[i] += stiffness[i] * p.density[i];
    const float own = stiffness[i] / p.density[i];
    Vec3 a{};
    const NeighborList& liquid = p.liquid_pairs.list;
    for (std::uint32_t k = liquid.offset[i]; k < liquid.offset[i + 1]; ++k) {
      const std::uint32_t j = liquid.index[k];
      if (j == i) continue;
      a -= (p.mass(j) * (own + stiffness[j] / p.density[j])) * p.liquid_gradient(i, k);
    }
    const NeighborList& rigid = p.rigid_pairs.list;
    for (std::uint32_t k = rigid.offset[i]; k < rigid.offset[i + 1]; ++k)
      a -= (p.rest_density * p.rigid_volume[rigid.index[k]] * own) * p.rigid_gradient(i, k);
    target[i] += scale * a;
  }
};

// The pressure a step applies is the two solves' together: the divergence
// solve's velocity changes act over the step as the density solve's
// accelerations do (a liquid at rest gets about a tenth of its hydrostatic
// support from them).
struct ClearDivergencePressure {
  float* divergence_pressure;
  DP_HD void operator()(std::size_t i) const { divergence_pressure[i] = 0.0f; }
};

struct AddDivergencePressure {
  const float* divergence_pressure;
  float* pressure;
  DP_HD void operator()(std::size_t i) const { pressure[i] += divergence_pressure[i]; }
};

}  // namespace dp
