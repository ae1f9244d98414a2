#pragma once
// Viscosity of Morris, Fox & Zhu 1997 ("Modeling low Reynolds number
// incompressible flows using SPH", J. Comput. Phys. 136, Eq. 8): the SPH
// Laplacian of the velocity built from the kernel's first derivative,
//
//   a_i = sum_j m_j (mu_i + mu_j) / (rho_i rho_j) (x_ij . gradW_ij) / (|x_ij|^2 + eta^2) (v_i - v_j),
//
// with mu = rho nu, eta^2 = 0.01 h_M^2 (h_M the smoothing length, half our
// support h). Unlike XSPH it takes a physical kinematic viscosity nu (m^2/s)
// and acts as a rate, so it does not depend on the time step or, beyond
// discretisation error, on the particle spacing.
//
// Walls are no-slip: each boundary particle (Akinci 2012) is a particle of
// liquid at rest with the wall (Morris et al.'s boundary particles with
// d_B = 0, since ours lie on the rigid's surface). It stands for the liquid
// layer one spacing deep over the wall area it samples, A_b s; Akinci's
// volume V_b = 1 / sum_k W_bk gives that area as A_b = V_b Int_plane W dA
// on a flat, evenly sampled wall, which keeps the term right where a wall is
// sampled finer or coarser than the liquid.
//
// Where the first liquid layer lies outside the viscous sublayer, as it does
// at any practical spacing in a flow of water at speed, a resolved no-slip
// wall gives the laminar shear rho nu u / y, far below the real one. With
// WallShear::Spalding1961 the wall-parallel part of the wall term takes the
// law of the wall's factor (sph/wall_shear_spalding1961.h); the
// wall-normal part stays laminar.
#include <cfloat>
#include <cstdint>

#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/neighbor_list.h"
#include "sph/sum_in_list_order.h"
#include "sph/uniform_grid.h"
#include "sph/wall_shear_spalding1961.h"

namespace dp {

// Morris et al. 1997 keep the denominator away from zero with 0.01 h_M^2.
DP_HD inline float morris_eta2(const CubicSplineKernel& kernel) { return 0.01f * (0.5f * kernel.h) * (0.5f * kernel.h); }

// Explicit integration of the viscous term is stable for
// dt <= 0.125 h_M^2 / nu (Morris et al. 1997, Eq. 22), h_M = h / 2.
inline float viscous_time_step_limit(const CubicSplineKernel& kernel, float kinematic_viscosity) {
  const float hm = 0.5f * kernel.h;
  return kinematic_viscosity > 0 ? 0.125f * hm * hm / kinematic_viscosity : 1e30f;
}

// The liquid volume a boundary particle of Akinci volume V_b stands for in
// the wall term: V_b times spacing times the kernel's integral over a plane
// through its centre (2 pi sigma h^2 * 7/80 = 1.4 / h for the cubic spline).
inline float wall_layer_volume_per_akinci_volume(const CubicSplineKernel& kernel, float spacing) {
  return spacing * 1.4f / kernel.h;
}

struct AddViscosityMorris1997 {
  GridView liquid;                  // sorted liquid positions
  GridView rigid;                   // rigid boundary particles
  const MassUnits* units;           // w_i
  const float* density;             // rho_i, kg/m^3
  const float* rigid_volume;        // V_b, m^3 (Akinci 2012, Eq. 4)
  const Vec3* velocity;             // v_i, m/s
  CubicSplineKernel kernel;
  float particle_mass;              // kg, a full particle
  float kinematic_viscosity;        // nu, m^2/s
  float wall_layer_volume_factor;   // wall_layer_volume_per_akinci_volume
  Vec3* acceleration;               // m/s^2, added to
  ListedPairs liquid_pairs{}, rigid_pairs{};
  WallShear wall_shear = WallShear::NoSlip;

  DP_HD Vec3 between_liquid(std::size_t i) const {
    const Vec3 xi = liquid.position[i], vi = velocity[i];
    const float rhoi = density[i], eta2 = morris_eta2(kernel);
    Vec3 a{};
    for_each_pair_gradient(liquid, liquid_pairs, i, xi, kernel, [&](std::uint32_t j, Vec3 xij, Vec3 gradW) {
      if (j == i) return;
      a += liquid_term(rhoi, vi, j, xij, gradW, eta2);
    });
    return a;
  }

  // between_liquid over the step's list by sum_in_list_order.h (the CPU's,
  // for lists up to kMaxTermsInOrder).
  DP_HOST_INLINE Vec3 between_liquid_listed(std::size_t i) const {
    const Vec3 xi = liquid.position[i], vi = velocity[i];
    const float rhoi = density[i], eta2 = morris_eta2(kernel);
    const std::uint32_t first = liquid_pairs.list.offset[i];
    return vector_sum_in_list_order(Vec3{}, liquid_pairs.list.offset[i + 1] - first, [&](std::uint32_t k) {
      const std::uint32_t j = liquid_pairs.list.index[first + k];
      const Vec3 xij = xi - liquid.position[j];
      return keep_if(liquid_term(rhoi, vi, j, xij, liquid_pairs.gradient_factor[first + k] * xij, eta2), j != i);
    });
  }

  // Morris's Eq. 8 for one pair, mu = rho nu.
  DP_HD Vec3 liquid_term(float rhoi, Vec3 vi, std::uint32_t j, Vec3 xij, Vec3 gradW, float eta2) const {
    const float rhoj = density[j];
    const float mj = particle_mass * weight_of(units[j]);
    const float mu_sum_over_rho2 = kinematic_viscosity * (rhoi + rhoj) / (rhoi * rhoj);
    return (mj * mu_sum_over_rho2 * dot(xij, gradW) / (length_squared(xij) + eta2)) * (vi - velocity[j]);
  }

  // The wall's particle carries the liquid's density rho_i, so its
  // (mu_i + mu_b) / (rho_i rho_b) m_b is 2 nu V.
  // Always inlined, into the launcher's AVX2 copy too (docs/architecture.md).
  DP_HD_INLINE Vec3 against_walls(std::size_t i) const {
    const Vec3 xi = liquid.position[i], vi = velocity[i];
    const float eta2 = morris_eta2(kernel);
    const bool wall_law = wall_shear == WallShear::Spalding1961;
    float sum = 0.0f;
    Vec3 into_wall{}, from_nearest{};  // read by the wall law only
    float nearest2 = FLT_MAX;
    for_each_pair_gradient(rigid, rigid_pairs, i, xi, kernel, [&](std::uint32_t b, Vec3 xib, Vec3 gradW) {
      const float volume = wall_layer_volume_factor * rigid_volume[b];
      const float r2 = length_squared(xib);
      sum += 2.0f * kinematic_viscosity * volume * dot(xib, gradW) / (r2 + eta2);
      if (!wall_law) return;
      into_wall += rigid_volume[b] * gradW;
      if (r2 < nearest2) {
        nearest2 = r2;
        from_nearest = xib;
      }
    });
    if (!wall_law || sum == 0.0f) return sum * vi;
    return sum * with_wall_law(vi, into_wall, from_nearest);
  }

  // v with its wall-parallel part scaled by Spalding's factor. The wall's
  // normal is the boundary's kernel gradient, as in Akinci's boundary
  // density; the wall distance is the nearest boundary particle's along it
  // (exact on a flat, evenly sampled wall).
  DP_HD Vec3 with_wall_law(Vec3 v, Vec3 into_wall, Vec3 from_nearest) const {
    const float norm = length(into_wall);
    if (norm == 0.0f) return v;
    const Vec3 n = into_wall * (-1.0f / norm);  // out of the wall
    const Vec3 normal_part = dot(v, n) * n, parallel = v - normal_part;
    const float distance = fmaxf(dot(from_nearest, n), 0.0f);
    return normal_part + wall_shear_factor_spalding1961(length(parallel), distance, kinematic_viscosity) * parallel;
  }

  DP_HD void operator()(std::size_t i) const { add(i, between_liquid(i)); }

  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    for (std::size_t i = begin; i < end; ++i) {
      const bool listed = liquid_pairs.present() && fits_in_list_order(liquid_pairs.list, i);
      add(i, listed ? between_liquid_listed(i) : between_liquid(i));
    }
  }

  DP_HD void add(std::size_t i, Vec3 a) const {
    if (rigid_volume) a += against_walls(i);
    acceleration[i] += a;
  }
};

}  // namespace dp
