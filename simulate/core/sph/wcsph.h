#pragma once
// Weakly compressible SPH (Becker & Teschner 2007) with rigid boundary
// particles (Akinci et al. 2012): per-particle kernels, each gathering over
// its neighbours and writing only its own element.
#include <cstdint>

#include "backend/host_device.h"
#include "math/vec3.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/uniform_grid.h"

namespace dp {

struct WcsphParameters {
  CubicSplineKernel kernel;
  float particle_mass;
  float rest_density;
  float stiffness;  // B = rho0 c^2 / gamma
  float speed_of_sound;
  float viscosity_alpha;
  float boundary_friction;
  Vec3 gravity;
};

// Tait's equation of state, clamped at zero so the free surface does not
// pull particles together (tensile instability).
DP_HD inline float tait_pressure(float density, float rest_density, float stiffness) {
  float ratio = density / rest_density;
  float r2 = ratio * ratio, r4 = r2 * r2;
  float p = stiffness * (r4 * r2 * ratio - 1.0f);
  return p > 0.0f ? p : 0.0f;
}

// Akinci et al. 2012, Eq. 4: the volume of a boundary particle is the
// inverse of its boundary neighbours' kernel sum, so densely sampled
// regions do not over-count.
struct ComputeBoundaryVolume {
  GridView rigid;
  CubicSplineKernel kernel;
  float* volume;
  DP_HD void operator()(std::size_t b) const {
    Vec3 xb = rigid.position[b];
    float sum = 0.0f;
    rigid.for_each_near(xb, [&](std::uint32_t k) { sum += kernel.W(length(xb - rigid.position[k])); });
    volume[b] = 1.0f / sum;
  }
};

// rho_i = sum_j m_j W_ij + sum_b Psi_b W_ib with Psi_b = rho0 V_b (Akinci 2012, Eq. 6).
struct ComputeDensityAndPressure {
  GridView liquid;
  GridView rigid;
  const float* rigid_volume;
  WcsphParameters p;
  float* density;
  float* pressure;
  DP_HD void operator()(std::size_t i) const {
    Vec3 xi = liquid.position[i];
    float rho = 0.0f;
    const float h2 = p.kernel.h * p.kernel.h;
    // Most of the 27 cells' particles lie outside the support: reject them
    // on the squared distance before the square root.
    liquid.for_each_near(xi, [&](std::uint32_t j) {
      float r2 = length_squared(xi - liquid.position[j]);
      if (r2 < h2) rho += p.particle_mass * p.kernel.W(sqrtf(r2));
    });
    rigid.for_each_near(xi, [&](std::uint32_t b) {
      float r2 = length_squared(xi - rigid.position[b]);
      if (r2 < h2) rho += p.rest_density * rigid_volume[b] * p.kernel.W(sqrtf(r2));
    });
    density[i] = rho;
    pressure[i] = tait_pressure(rho, p.rest_density, p.stiffness);
  }
};

// Monaghan's artificial viscosity term Pi_ij (zero for separating pairs).
DP_HD inline float artificial_viscosity(Vec3 xij, Vec3 vij, float alpha, float smoothing_length, float c,
                                        float mean_density) {
  float vx = dot(vij, xij);
  if (vx >= 0.0f) return 0.0f;
  float nu = 2.0f * alpha * smoothing_length * c / mean_density;
  return -nu * vx / (dot(xij, xij) + 0.01f * smoothing_length * smoothing_length);
}

// Pressure (symmetric form), viscosity and gravity; rigid particles push with
// Psi_b p_i / rho_i^2 (Akinci 2012, Eq. 10) and add friction.
struct ComputeAcceleration {
  GridView liquid;
  GridView rigid;
  const float* rigid_volume;
  const Vec3* velocity;
  const float* density;
  const float* pressure;
  WcsphParameters p;
  Vec3* acceleration;
  DP_HD void operator()(std::size_t i) const {
    Vec3 xi = liquid.position[i], vi = velocity[i];
    float rhoi = density[i], pi_rho2 = pressure[i] / (rhoi * rhoi);
    float hs = 0.5f * p.kernel.h;  // smoothing length
    const float h2 = p.kernel.h * p.kernel.h;
    Vec3 a = p.gravity;
    liquid.for_each_near(xi, [&](std::uint32_t j) {
      Vec3 xij = xi - liquid.position[j];
      if (j == i || length_squared(xij) >= h2) return;
      Vec3 grad = p.kernel.gradW(xij);
      float pj_rho2 = pressure[j] / (density[j] * density[j]);
      float visc = artificial_viscosity(xij, vi - velocity[j], p.viscosity_alpha, hs, p.speed_of_sound,
                                        0.5f * (rhoi + density[j]));
      a -= (p.particle_mass * (pi_rho2 + pj_rho2 + visc)) * grad;
    });
    rigid.for_each_near(xi, [&](std::uint32_t b) {
      Vec3 xib = xi - rigid.position[b];
      if (length_squared(xib) >= h2) return;
      Vec3 grad = p.kernel.gradW(xib);
      float psi = p.rest_density * rigid_volume[b];
      float visc = artificial_viscosity(xib, vi, p.boundary_friction, hs, p.speed_of_sound, rhoi);
      a -= (psi * (pi_rho2 + visc)) * grad;
    });
    acceleration[i] = a;
  }
};

// Symplectic Euler.
struct Integrate {
  const Vec3* acceleration;
  float dt;
  Vec3* velocity;
  Vec3* position;
  DP_HD void operator()(std::size_t i) const {
    velocity[i] += dt * acceleration[i];
    position[i] += dt * velocity[i];
  }
};

}  // namespace dp
