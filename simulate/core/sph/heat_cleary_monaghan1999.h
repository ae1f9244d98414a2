#pragma once
// Heat conduction between particles (paper Sec. 3.3, Eq. 9), after Cleary &
// Monaghan 1999, "Conduction Modelling Using Smoothed Particle
// Hydrodynamics" (J. Comput. Phys. 148), for liquid and rigid particles
// alike:
//
//   m_i C_i dT_i/dt = V_i sum_j k_ij V_j (T_i - T_j) F_ij,
//   k_ij = 4 kappa_i kappa_j / (kappa_i + kappa_j),   F_ij = x_ij . grad_i W_ij / |x_ij|^2 <= 0.
//
// Cleary & Monaghan write the sum with m_j / (rho_i rho_j); with
// V = m / rho and the paper's V_i / m_i = 1 / rho_i this is the same
// expression. It is the Brookshaw (1985) Laplacian, 2 sum_j V_j (T_i - T_j)
// F_ij, with 2 kappa replaced by k_ij: twice the harmonic mean, which equals
// 2 kappa for one material and keeps the heat flux continuous across a jump
// in kappa, the point of Cleary & Monaghan's paper. Since F_ij <= 0, heat
// flows from hot to cold. The paper's Eq. 9 prints the kernel term as
// grad W_ij / |x_ij|; the scalar x_ij . grad W_ij / |x_ij|^2 used here is
// Cleary & Monaghan's. They also add a small eta^2 to |x_ij|^2 against
// coincident particles; the cubic spline's F_ij stays bounded as r -> 0
// (dW/dr vanishes linearly), so we leave eta out rather than bias near
// neighbours, and skip only exactly coincident pairs. F_ij equals W'(r) / r,
// the gradient factor the step's lists keep; reading it from there instead
// of dividing would round differently and move every frame's bits, which a
// change for speed must not do (tried: 5 ms of the settled glass's Heat,
// and the drop's image regression moved).
//
// Each pair term is antisymmetric in i, j (k_ij, V_i V_j and F_ij are
// symmetric, T_i - T_j is not), so the total thermal energy sum_i m_i C_i T_i
// of an isolated system is conserved up to rounding, for any mix of
// materials, as long as each particle's V and m are the same whether it is
// the one updated or the neighbour. The functors below therefore take V_i
// and m_i from one place, ThermalParticles.
#include <cstdint>

#include "backend/host_device.h"
#include "math/keep_if.h"
#include "math/vec3.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/neighbor_list.h"
#include "sph/sum_in_list_order.h"
#include "sph/uniform_grid.h"

namespace dp {

// One set of particles of one material, as the heat kernels see it. A
// liquid particle's volume follows from its adaptive mass and density
// (V = w m / rho, paper Sec. 4.1; ParticleMass and ParticleVolume, once a
// step); a rigid particle's is its Akinci volume V_b, and its mass
// rho_material V_b.
struct ThermalParticles {
  GridView grid;             // sorted positions
  const float* temperature;  // K (or any offset scale), sorted like the positions
  const float* volume;       // V_j, m^3
  const float* mass;         // liquid: m_j, kg; null for a rigid set
  float material_density;    // rigid: kg/m^3
  float conductivity;        // kappa, W/(m K)
  float specific_heat;       // C, J/(kg K)

  static ThermalParticles liquid(GridView grid, const float* temperature, const float* mass, const float* volume,
                                 float conductivity, float specific_heat) {
    return ThermalParticles{grid, temperature, volume, mass, 0.0f, conductivity, specific_heat};
  }
  static ThermalParticles rigid(GridView grid, const float* temperature, const float* volume,
                                float material_density, float conductivity, float specific_heat) {
    return ThermalParticles{grid, temperature, volume, nullptr, material_density, conductivity, specific_heat};
  }

  DP_HD float mass_of(std::uint32_t j) const { return mass ? mass[j] : material_density * volume[j]; }
};

// F_ij = x_ij . grad_i W_ij / |x_ij|^2, for |x_ij|^2 = r2 in (0, h^2).
DP_HD inline float conduction_kernel_factor(Vec3 xij, Vec3 grad, float r2) { return dot(xij, grad) / r2; }

// k_ij of Cleary & Monaghan: twice the harmonic mean of the conductivities.
DP_HD inline float pair_conductivity(float kappa_i, float kappa_j) {
  float sum = kappa_i + kappa_j;
  return sum > 0.0f ? 4.0f * kappa_i * kappa_j / sum : 0.0f;
}

// dT_i/dt of particle i of `self`, from its own set and, if `with_other`,
// from a second set (liquid <-> rigid). Writes rate[i], K/s.
struct ComputeTemperatureRate {
  ThermalParticles self;
  ThermalParticles other;
  bool with_other;
  CubicSplineKernel kernel;
  float* rate;
  ListedPairs self_pairs{}, other_pairs{};  // the step's lists for i, if any
  // The CPU's other set around i where other_pairs has no list: the same
  // particles in the same order as a walk of its grid (a TransposedList).
  // Null: walked (gather_near).
  NeighborList other_near{nullptr, nullptr};

  static constexpr std::uint32_t kNobody = 0xffffffffu;

  // V_j (T_i - T_j) F_ij, the pair's term before k_ij.
  DP_HD static float pair_term(const ThermalParticles& set, std::uint32_t j, float ti, Vec3 xij, Vec3 grad, float r2) {
    return set.volume[j] * (ti - set.temperature[j]) * conduction_kernel_factor(xij, grad, r2);
  }

  // sum_j k_ij V_j (T_i - T_j) F_ij over the neighbours in `set`, with
  // `skip` = i in its own set (no index matches otherwise).
  DP_HD float exchange_with(const ThermalParticles& set, const ListedPairs& pairs, std::size_t i, float ti,
                            std::uint32_t skip) const {
    float sum = 0.0f;
    for_each_pair_gradient(set.grid, pairs, i, self.grid.position[i], kernel, [&](std::uint32_t j, Vec3 xij, Vec3 grad) {
      const float r2 = length_squared(xij);
      if (j == skip || r2 <= 0.0f) return;
      sum += pair_term(set, j, ti, xij, grad, r2);
    });
    return pair_conductivity(self.conductivity, set.conductivity) * sum;
  }

  DP_HD float rate_from(std::size_t i, float exchange) const {
    return self.volume[i] * exchange / (self.mass_of(static_cast<std::uint32_t>(i)) * self.specific_heat);
  }

  DP_HD void operator()(std::size_t i) const {
    const float ti = self.temperature[i];
    float exchange = exchange_with(self, self_pairs, i, ti, static_cast<std::uint32_t>(i));
    if (with_other) exchange += exchange_with(other, other_pairs, i, ti, kNobody);
    rate[i] = rate_from(i, exchange);
  }

  // Elements begin .. end - 1 at once (CpuExec), each sum with its terms
  // first (sum_in_list_order.h); a set without a list (the liquid around a
  // rigid particle) is walked by gather_near. Same pairs, same order, same
  // bits as operator().
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    for (std::size_t i = begin; i < end; ++i) {
      const float ti = self.temperature[i];
      float exchange = 0.0f;
      if (!exchange_in_list_order(self, self_pairs, NeighborList{nullptr, nullptr}, i, ti, static_cast<std::uint32_t>(i), exchange) ||
          (with_other && !exchange_in_list_order(other, other_pairs, other_near, i, ti, kNobody, exchange))) {
        (*this)(i);
        continue;
      }
      rate[i] = rate_from(i, exchange);
    }
  }

 private:
  // exchange += k_ij sum_j ..., as exchange_with adds it; false where the
  // neighbours do not fit the terms' arrays. Without a list in `pairs`,
  // the neighbours are `near_list`'s or, where it is null, walked.
  DP_HOST_INLINE bool exchange_in_list_order(const ThermalParticles& set, const ListedPairs& pairs, const NeighborList& near_list,
                                             std::size_t i, float ti, std::uint32_t skip, float& exchange) const {
    const Vec3 xi = self.grid.position[i];
    const auto term = [&](std::uint32_t j, Vec3 xij, Vec3 grad) {
      const float r2 = length_squared(xij);
      return keep_if(pair_term(set, j, ti, xij, grad, r2), (j != skip) & (r2 > 0.0f));
    };
    float sum = 0.0f;
    if (pairs.present()) {
      if (!fits_in_list_order(pairs.list, i)) return false;
      const std::uint32_t first = pairs.list.offset[i];
      sum = sum_in_list_order(0.0f, pairs.list.offset[i + 1] - first, [&](std::uint32_t k) {
        const std::uint32_t j = pairs.list.index[first + k];
        const Vec3 xij = xi - set.grid.position[j];
        return term(j, xij, pairs.gradient_factor[first + k] * xij);
      });
    } else {
      std::uint32_t walked[kMaxTermsInOrder + kNearBlock];
      const std::uint32_t* near = walked;
      std::uint32_t count;
      if (near_list.offset) {
        near = near_list.index + near_list.offset[i];
        count = near_list.offset[i + 1] - near_list.offset[i];
      } else {
        count = gather_near(set.grid, xi, kernel.h * kernel.h, walked, kMaxTermsInOrder);
      }
      if (count > kMaxTermsInOrder) return false;
      sum = sum_in_list_order(0.0f, count, [&](std::uint32_t k) {
        const std::uint32_t j = near[k];
        const Vec3 xij = xi - set.grid.position[j];
        return term(j, xij, kernel.gradW(xij));
      });
    }
    exchange += pair_conductivity(self.conductivity, set.conductivity) * sum;
    return true;
  }
};

// Explicit Euler, T_i += dt dT_i/dt, except where held[i] != 0: such
// particles (e.g. a heated plate) keep the temperature the caller set.
// `held` may be null: nothing is held.
struct IntegrateTemperature {
  const float* rate;
  const std::uint8_t* held;
  float dt;
  float* temperature;
  DP_HD void operator()(std::size_t i) const {
    if (held && held[i]) return;
    temperature[i] += dt * rate[i];
  }
};

// The largest dt for which explicit Euler keeps every new temperature a
// convex combination of old ones (no overshoot, hence stable):
// dt <= 1 / a_ii with a_ii = k_ij / (rho_i C_i) sum_j V_j |F_ij|. In the
// continuum, sum_j V_j |F_ij| = 4 pi int_0^h W dr = 12 / h^2 for the cubic
// spline, and k_ij = 2 kappa for one material, so
//
//   dt <= rho C h^2 / (24 kappa),   i.e. c = 1/24.
//
// At h = 2 spacings this is spacing^2 / (6 alpha), the bound of the 7-point
// finite-difference stencil. The continuum sum exceeds the lattice sums
// (8.8 / h^2 at h = 2 spacings, 11.1 / h^2 at 3), which leaves a margin for
// disordered or compressed neighbourhoods. Between materials k_ij exceeds
// 2 kappa_i by up to 2x: pass kappa = the largest k_ij / 2 over the
// materials a particle touches (its own kappa, or the harmonic mean
// 2 kappa_i kappa_j / (kappa_i + kappa_j)), and take the smallest dt over
// all materials.
inline float heat_time_step_limit(const CubicSplineKernel& kernel, float density, float specific_heat,
                                  float conductivity) {
  return density * specific_heat * kernel.h * kernel.h / (24.0f * conductivity);
}

}  // namespace dp
