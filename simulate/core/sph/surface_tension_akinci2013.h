#pragma once
// Surface tension and adhesion of Akinci, Akinci & Teschner 2013, "Versatile
// Surface Tension and Adhesion for SPH Fluids" (ACM TOG 32(6)), which the
// paper uses for its particles (Sec. 4.1). Two liquid-liquid forces act
// between neighbours i, j: cohesion, a short-range pair potential that pulls
// particles at mid distances together and pushes very close ones apart, and
// a curvature term on the difference of neighbouring surface normals
// (Akinci's surface-area minimisation). Liquid-boundary adhesion pulls
// liquid particles towards rigid boundary particles (Akinci 2012 sampling).
//
// Units. Lengths in m, masses in kg, densities in kg/m^3; the functors yield
// accelerations in m/s^2. Both kernels C and A are in m^-3. The model is
// dimensionally loose, as published: one coefficient gamma scales the
// cohesion acceleration gamma m_j C (gamma in m^4 kg^-1 s^-2) and the
// curvature acceleration gamma (n_i - n_j) with dimensionless normals (gamma
// in m s^-2). gamma and beta are therefore tuned per resolution (for the
// same effective surface tension and rest density both scale about as
// 1 / h^2), and the numbers are meaningful for the SI quantities stated here.
//
// Adaptive masses (paper Sec. 4.1): particles carry m_i = w_i m. The paper
// (Akinci) assumes equal masses; where its formula has m_i in a pair force
// that must be antisymmetric, the pair's harmonic mean mass is used instead
// (see curvature_mass_ratio).
#include <cstddef>
#include <cstdint>

#include "backend/host_device.h"
#include "math/keep_if.h"
#include "math/vec3.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/neighbor_list.h"
#include "sph/sum_in_list_order.h"
#include "sph/uniform_grid.h"

namespace dp {

// Akinci 2013, Eq. 2, with support radius h:
//   C(r) = 32 / (pi h^9) * (h - r)^3 r^3                 for h/2 < r <= h
//          32 / (pi h^9) * (2 (h - r)^3 r^3 - h^6 / 64)  for 0 < r <= h/2
//          0                                            otherwise.
// Positive values attract. The inner branch turns repulsive below the root
// of 2 (h - r)^3 r^3 = h^6 / 64, which keeps clustering particles apart
// even where a clamped pressure does not.
struct AkinciCohesionKernel {
  float h;
  float scale;  // 32 / (pi h^9)

  DP_HD static AkinciCohesionKernel with_support(float h) {
    float h3 = h * h * h;
    return AkinciCohesionKernel{h, 32.0f / (3.14159265358979f * h3 * h3 * h3)};
  }

  DP_HD float C(float r) const {
    if (r <= 0.0f || r > h) return 0.0f;
    float outer = (h - r) * r;
    float pair_term = outer * outer * outer;  // (h - r)^3 r^3
    if (2.0f * r > h) return scale * pair_term;
    float h3 = h * h * h;
    return scale * (2.0f * pair_term - h3 * h3 * (1.0f / 64.0f));
  }

  // C with both pieces computed and one selected on their bits: the same
  // value, for loops that vectorise (sum_in_list_order.h).
  DP_HD float C_selected(float r) const {
    const float outer = (h - r) * r;
    const float pair_term = outer * outer * outer;
    const float h3 = h * h * h;
    const float c = pick_if(2.0f * r > h, scale * pair_term, scale * (2.0f * pair_term - h3 * h3 * (1.0f / 64.0f)));
    return keep_if(c, (r > 0.0f) & (r <= h));
  }
};

// Akinci 2013, Eq. 7:
//   A(r) = 0.007 / h^3.25 * (-4 r^2 / h + 6 r - 2 h)^(1/4)   for h/2 < r <= h
//          0                                                otherwise.
// It attracts only between h/2 and h, most strongly at r = 3h/4: closer in,
// the boundary's pressure acts alone, so adhesion draws liquid to the wall
// without pressing it into the boundary particles.
struct AkinciAdhesionKernel {
  float h;
  float scale;  // 0.007 / h^3.25

  DP_HD static AkinciAdhesionKernel with_support(float h) { return AkinciAdhesionKernel{h, 0.007f / powf(h, 3.25f)}; }

  DP_HD float A(float r) const {
    if (2.0f * r <= h || r > h) return 0.0f;
    float radicand = -4.0f * r * r / h + 6.0f * r - 2.0f * h;
    // Rounding can leave the radicand a hair below zero at the range's ends.
    if (radicand <= 0.0f) return 0.0f;
    return scale * sqrtf(sqrtf(radicand));
  }

  // A without branches, as AkinciCohesionKernel::C_selected.
  DP_HD float A_selected(float r) const {
    const float radicand = -4.0f * r * r / h + 6.0f * r - 2.0f * h;
    return keep_if(scale * sqrtf(sqrtf(radicand)), (2.0f * r > h) & (r <= h) & (radicand > 0.0f));
  }
};

// Correction factor of Akinci 2013, Eq. 5: K_ij = 2 rho0 / (rho_i + rho_j).
// Particles at the surface lack neighbours, so their densities are low and
// K_ij > 1 amplifies the forces there, where surface tension belongs.
DP_HD inline float surface_deficiency_factor(float rest_density, float density_i, float density_j) {
  return 2.0f * rest_density / (density_i + density_j);
}

// The curvature force of Akinci 2013, Eq. 4, is -gamma m_i (n_i - n_j):
// with unequal masses the forces on i and on j would not be opposite, and
// the liquid would gain momentum from nothing. The pair's harmonic mean
// 2 m_i m_j / (m_i + m_j) replaces m_i; it equals m_i for equal masses (the
// published case) and, unlike the arithmetic mean, keeps a light particle's
// acceleration below twice the equal-mass value. Returned divided by m_i,
// for an acceleration.
DP_HD inline float curvature_mass_ratio(float mass_i, float mass_j) { return 2.0f * mass_j / (mass_i + mass_j); }

// Akinci 2013, Eq. 3: n_i = h sum_j (m_j / rho_j) grad W_ij, the colour
// field's gradient scaled by the support radius so that |n| is of order 1 at
// the surface and near 0 inside. As published it points into the liquid
// (grad_i W_ij points from i towards j); the curvature term is written for
// that orientation, and with the opposite one the liquid tears into clumps.
struct ComputeSurfaceNormal {
  GridView liquid;          // sorted liquid positions
  const MassUnits* units;   // w_j, in mass units, sorted like the positions
  const float* density;     // rho_j, kg/m^3
  CubicSplineKernel kernel;
  float particle_mass;      // m of a full particle, kg
  Vec3* normal;             // dimensionless
  ListedPairs pairs{};      // the step's liquid list, if any
  // Always inlined, into the launcher's AVX2 copy too (docs/architecture.md).
  DP_HD_INLINE void operator()(std::size_t i) const {
    Vec3 n{};
    for_each_pair_gradient(liquid, pairs, i, liquid.position[i], kernel, [&](std::uint32_t j, Vec3, Vec3 grad) {
      if (j != i) n += (particle_mass * weight_of(units[j]) / density[j]) * grad;
    });
    normal[i] = kernel.h * n;
  }
};

struct SurfaceTensionParameters {
  CubicSplineKernel kernel;  // the liquid's kernel; h is also the cohesion/adhesion support
  float particle_mass;       // m of a full particle, kg
  float rest_density;        // rho0, kg/m^3
  float tension;             // gamma of the liquid (see the units above)
};

// Cohesion plus curvature, summed over liquid neighbours (Akinci 2013,
// Eq. 1-5), and adhesion to boundary particles (Eq. 6), as one acceleration:
//   a_i = sum_j K_ij (-gamma m_j C(r_ij) x_ij / r_ij - gamma (2 m_j / (m_i + m_j)) (n_i - n_j))
//       + sum_b -beta_b Psi_b A(r_ib) x_ib / r_ib,        Psi_b = rho0 V_b.
// Writes acceleration[i] (the surface tension contribution only; the step
// adds it to the others).
struct ComputeSurfaceTensionAcceleration {
  GridView liquid;              // sorted liquid positions
  GridView rigid;               // rigid boundary particles
  const MassUnits* units;       // w_i, sorted like the liquid positions
  const float* density;         // rho_i, kg/m^3
  const Vec3* normal;           // from ComputeSurfaceNormal
  const float* rigid_volume;    // V_b, m^3 (Akinci 2012, Eq. 4)
  const float* rigid_adhesion;  // beta of the rigid material each boundary particle samples
  SurfaceTensionParameters p;
  Vec3* acceleration;           // m/s^2
  ListedPairs liquid_pairs{}, rigid_pairs{};  // the step's lists, if any

  DP_HD Vec3 cohesion_and_curvature(std::size_t i) const {
    const Vec3 xi = liquid.position[i], ni = normal[i];
    const float mi = p.particle_mass * weight_of(units[i]), rhoi = density[i];
    const AkinciCohesionKernel cohesion = AkinciCohesionKernel::with_support(p.kernel.h);
    Vec3 a{};
    for_each_pair(liquid, liquid_pairs, i, xi, p.kernel.h, [&](std::uint32_t j, Vec3 xij, std::uint32_t) {
      const float r2 = length_squared(xij);
      if (j == i) return;
      Vec3 pair = curvature_term(mi, ni, j);
      // Coincident particles have no direction to attract along.
      if (r2 > 0.0f) {
        float r = sqrtf(r2);
        pair -= cohesion_term(j, cohesion.C(r), r, xij);
      }
      a += pair_weight(rhoi, j) * pair;
    });
    return a;
  }

  DP_HD Vec3 adhesion_to_boundary(std::size_t i) const {
    const AkinciAdhesionKernel adhesion = AkinciAdhesionKernel::with_support(p.kernel.h);
    Vec3 a{};
    for_each_pair(rigid, rigid_pairs, i, liquid.position[i], p.kernel.h, [&](std::uint32_t b, Vec3 xib, std::uint32_t) {
      const float r2 = length_squared(xib);
      if (r2 <= 0.0f) return;
      float r = sqrtf(r2);
      a -= adhesion_term(b, adhesion.A(r), r, xib);
    });
    return a;
  }

  DP_HD void operator()(std::size_t i) const { acceleration[i] = cohesion_and_curvature(i) + adhesion_to_boundary(i); }

  // The CPU's, over the step's lists: the same sums by sum_in_list_order.h.
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    const AkinciCohesionKernel cohesion = AkinciCohesionKernel::with_support(p.kernel.h);
    const AkinciAdhesionKernel adhesion = AkinciAdhesionKernel::with_support(p.kernel.h);
    const NeighborList& liquid_list = liquid_pairs.list;
    const NeighborList& rigid_list = rigid_pairs.list;
    for (std::size_t i = begin; i < end; ++i) {
      if (!liquid_pairs.present() || !rigid_pairs.present() || !fits_in_list_order(liquid_list, i) ||
          !fits_in_list_order(rigid_list, i)) {
        (*this)(i);
        continue;
      }
      const std::uint32_t liquid_count = liquid_list.offset[i + 1] - liquid_list.offset[i];
      const std::uint32_t rigid_count = rigid_list.offset[i + 1] - rigid_list.offset[i];
      const Vec3 xi = liquid.position[i], ni = normal[i];
      const float mi = p.particle_mass * weight_of(units[i]), rhoi = density[i];
      const std::uint32_t* near = liquid_list.index + liquid_list.offset[i];
      const Vec3 tension = vector_sum_in_list_order(Vec3{}, liquid_count, [&](std::uint32_t k) {
        const std::uint32_t j = near[k];
        const Vec3 xij = xi - liquid.position[j];
        const float r2 = length_squared(xij), r = sqrtf(r2);
        const Vec3 pair = curvature_term(mi, ni, j) - keep_if(cohesion_term(j, cohesion.C_selected(r), r, xij), r2 > 0.0f);
        return keep_if(pair_weight(rhoi, j) * pair, j != i);
      });
      const std::uint32_t* walls = rigid_list.index + rigid_list.offset[i];
      const Vec3 adhering = vector_sum_in_list_order(Vec3{}, rigid_count, [&](std::uint32_t k) {
        const std::uint32_t b = walls[k];
        const Vec3 xib = xi - rigid.position[b];
        const float r2 = length_squared(xib), r = sqrtf(r2);
        return keep_if(-adhesion_term(b, adhesion.A_selected(r), r, xib), r2 > 0.0f);
      });
      acceleration[i] = tension + adhering;
    }
  }

 private:
  // Eq. 4's pair force over m_i, with the pair's harmonic-mean mass.
  DP_HD Vec3 curvature_term(float mi, Vec3 ni, std::uint32_t j) const {
    return -curvature_mass_ratio(mi, p.particle_mass * weight_of(units[j])) * (ni - normal[j]);
  }
  // Eq. 2's pair force over m_i and gamma, C = C(r).
  DP_HD Vec3 cohesion_term(std::uint32_t j, float c, float r, Vec3 xij) const {
    return (p.particle_mass * weight_of(units[j]) * c / r) * xij;
  }
  // gamma K_ij (Eq. 5).
  DP_HD float pair_weight(float rhoi, std::uint32_t j) const { return p.tension * surface_deficiency_factor(p.rest_density, rhoi, density[j]); }
  // Eq. 6's pair force over m_i, A = A(r).
  DP_HD Vec3 adhesion_term(std::uint32_t b, float a, float r, Vec3 xib) const {
    const float psi = p.rest_density * rigid_volume[b];
    return (rigid_adhesion[b] * psi * a / r) * xib;
  }
};

}  // namespace dp
