#pragma once
// The liquid's signed distance as Zhu & Bridson (2005) define it for
// particles, paper Eq. 19:
//   phi(x) = |x - xbar(x)| - rbar(x),
//   xbar = sum_i x_i Wbar_i(x),  rbar = sum_i r_i Wbar_i(x),
//   Wbar_i = k(|x - x_i| / R) / sum_j k(|x - x_j| / R),  k(s) = max(0, 1 - s^2)^3.
// Negative inside the liquid.
#include "liquid_particles.h"
#include "particle_cell_grid.h"
#include "scalar_grid.h"

namespace dp::mesh {

// Zhu-Bridson's kernel k(s), s = distance / R.
inline double zhu_bridson_kernel(double s_squared) {
  const double t = 1.0 - s_squared;
  return t > 0 ? t * t * t : 0.0;
}

class ZhuBridsonField {
 public:
  // Keeps references to `particles`, which must outlive the field.
  ZhuBridsonField(const LiquidParticles& particles, double kernel_radius);

  // phi(x) of Eq. 19. Where no particle lies within the kernel radius R the
  // weights are undefined (0/0): the point is outside, and phi is R, an
  // upper bound of how far the surface can be from there.
  double distance(Vec3d x) const;

  double kernel_radius() const { return kernel_radius_; }

 private:
  const LiquidParticles& particles_;
  double kernel_radius_;
  ParticleCellGrid neighbours_;
};

// The grid to mesh the particles on: their bounding box grown by R and two
// voxels, so the outermost nodes have no particle within R and lie outside;
// the surface then never touches the boundary and comes out closed.
GridBox zhu_bridson_grid_box(const LiquidParticles& particles, double kernel_radius, double voxel_size);

// phi of Eq. 19 at every node of `box`, in parallel over z-slabs.
ScalarGrid sample_zhu_bridson(const LiquidParticles& particles, double kernel_radius, const GridBox& box);

}  // namespace dp::mesh
