#pragma once
// A liquid particle's surface area A_i, the area through which it exchanges
// vapour and heat with the air (paper Sec. 4.1; A_s in Eq. 12, A_i in
// Eq. 14-15). The paper computes A_i "as proposed by Orthmann et al.
// [2013]" (Consistent Surface Model for SPH-based Fluid Transport, SCA
// 2013), whose abstract defines the free surface implicitly by giving each
// particle a value estimating its surface area; the formula itself was not
// available to us, so the estimate here is our own, built from published
// pieces:
//
//   A_i = gamma V_i |n_i|,   n_i = sum_j V_j grad W_ij  (minus what a wall hides)
//
// n_i is the gradient of the smoothed colour field (Morris 2000; Akinci
// 2013, Eq. 5 without the factor h), so |n| is a surface-area density and
// sum_i V_i |n_i| integrates it over the liquid. V_j = w_j m / rho_j with
// adaptive masses (Sec. 4.1). Two departures from the bare integral:
//
// * Particles sample only the liquid side of the smoothed interface, where
//   the colour falls from 1 to about 1/2, so the bare sum is about half the
//   area. gamma restores it: it is the value for which a flat face of a
//   simple cubic lattice at the rest spacing gets exactly its area
//   (flat_face_area_calibration), a property of the kernel and the spacing
//   only (1.96 at h = 2 spacings).
// * A wetted wall is not surface exposed to air. Optionally, rigid boundary
//   particles (Akinci 2012 volumes V_b) cancel the part of n_i that points
//   away from them, up to the strength of their own colour gradient
//   sum_b V_b grad W_ib (wall_hidden_part).
//
// Inside the liquid the neighbourhood is symmetric, n_i vanishes and so
// does A_i.
#include <cmath>
#include <cstdint>

#include "backend/host_device.h"
#include "math/vec3.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/neighbor_list.h"
#include "sph/uniform_grid.h"

namespace dp {

// The part of a liquid colour gradient n that a wall hides. Counting the
// wall as liquid (adding its gradient, -wall_strength * away) cancels the
// liquid's gradient along `away` (unit, from the wall into the liquid) only
// where the wall's Akinci volumes happen to match the missing liquid: a
// single-layer wall's volumes make up the missing density, not the missing
// gradient, so a particle a little closer than its rest distance would get
// more area from the wall than it lost. Hence the cancellation is clamped:
// a wall removes at most the component of n pointing away from it, and no
// more than its own gradient.
DP_HD inline Vec3 wall_hidden_part(Vec3 n, Vec3 away, float wall_strength) {
  float facing = dot(n, away);
  if (facing <= 0.0f) return Vec3{};
  return (facing < wall_strength ? facing : wall_strength) * away;
}

struct ComputeSurfaceArea {
  GridView liquid;               // sorted liquid positions
  const MassUnits* units;        // w_j, sorted like the positions
  const float* density;          // rho_j, kg/m^3
  float particle_mass;           // m of a full particle, kg
  GridView rigid;                // boundary particles; ignored unless with_rigid
  const float* rigid_volume;     // V_b, m^3 (Akinci 2012, Eq. 4)
  bool with_rigid;
  CubicSplineKernel kernel;
  float calibration;             // gamma, from flat_face_area_calibration
  float* area;                   // A_i, m^2, per sorted liquid particle
  // Optional: Akinci 2013 surface normals h sum_j V_j grad W_ij already
  // computed this step (ComputeSurfaceNormal); the liquid colour gradient is
  // then read from them instead of summed again.
  const Vec3* akinci_normal = nullptr;
  ListedPairs liquid_pairs{}, rigid_pairs{};  // the step's lists, if any

  DP_HD float volume_of(std::uint32_t j) const { return particle_mass * weight_of(units[j]) / density[j]; }

  // The colour gradient of the liquid alone, sum_j V_j grad W_ij.
  DP_HD Vec3 liquid_colour_gradient(std::size_t i) const {
    Vec3 n{};
    for_each_pair_gradient(liquid, liquid_pairs, i, liquid.position[i], kernel, [&](std::uint32_t j, Vec3, Vec3 grad) {
      if (j != i) n += volume_of(j) * grad;
    });
    return n;
  }

  // sum_b V_b grad W_ib: points from x_i towards the wall.
  DP_HD Vec3 rigid_colour_gradient(std::size_t i) const {
    Vec3 n{};
    for_each_pair_gradient(rigid, rigid_pairs, i, liquid.position[i], kernel,
                           [&](std::uint32_t b, Vec3, Vec3 grad) { n += rigid_volume[b] * grad; });
    return n;
  }

  DP_HD Vec3 colour_gradient(std::size_t i) const {
    Vec3 n = akinci_normal ? (1.0f / kernel.h) * akinci_normal[i] : liquid_colour_gradient(i);
    if (!with_rigid) return n;
    Vec3 wall = rigid_colour_gradient(i);
    float wall_strength = length(wall);
    if (wall_strength <= 0.0f) return n;
    return n - wall_hidden_part(n, (-1.0f / wall_strength) * wall, wall_strength);
  }

  DP_HD void operator()(std::size_t i) const {
    area[i] = calibration * volume_of(static_cast<std::uint32_t>(i)) * length(colour_gradient(i));
  }
};

// gamma such that the particles under one lattice cell of a flat face of a
// simple cubic lattice (spacing s, V = s^3, filling the half-space below the
// face) sum to s^2. Only the layers within h of the face have a gradient;
// each is summed over all lattice neighbours, in double.
inline float flat_face_area_calibration(const CubicSplineKernel& kernel, float spacing) {
  const int reach = static_cast<int>(std::ceil(kernel.h / spacing));
  const double volume = static_cast<double>(spacing) * spacing * spacing;
  double column = 0.0;  // sum over the layers below one face cell of V |n|
  for (int layer = 0; layer <= reach; ++layer) {
    double gx = 0, gy = 0, gz = 0;
    for (int k = -reach; k <= reach; ++k)
      for (int j = -reach; j <= reach; ++j)
        for (int i = -reach; i <= reach; ++i) {
          if (-layer + k > 0 || (i == 0 && j == 0 && k == 0)) continue;  // above the face, or itself
          Vec3 d{-i * spacing, -j * spacing, -k * spacing};
          Vec3 g = kernel.gradW(d);
          gx += volume * g.x;
          gy += volume * g.y;
          gz += volume * g.z;
        }
    column += volume * std::sqrt(gx * gx + gy * gy + gz * gz);
  }
  return static_cast<float>(static_cast<double>(spacing) * spacing / column);
}

}  // namespace dp
