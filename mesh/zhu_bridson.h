#pragma once
// The liquid's signed distance as Zhu & Bridson (2005) define it for
// particles, paper Eq. 19:
//   phi(x) = |x - xbar(x)| - rbar(x),
//   xbar = sum_i x_i Wbar_i(x),  rbar = sum_i r_i Wbar_i(x),
//   Wbar_i = k(|x - x_i| / R) / sum_j k(|x - x_j| / R),  k(s) = max(0, 1 - s^2)^3.
// Negative inside the liquid. The same weights average the particles'
// velocities, which the dynamic contact angles (Eq. 22-23) need.
#include "liquid_particles.h"
#include "particle_cell_grid.h"
#include "scalar_grid.h"

namespace dp::mesh {

// Zhu-Bridson's kernel k(s), s = distance / R.
inline double zhu_bridson_kernel(double s_squared) {
  const double t = 1.0 - s_squared;
  return t > 0 ? t * t * t : 0.0;
}

// Kernel-weighted sums over the particles near an evaluation point x.
struct KernelSums {
  double weight = 0;  // sum k_i
  Vec3d offset;       // sum k_i (x_i - x): xbar - x without cancelling large coordinates
  double radius = 0;  // sum k_i r_i
  Vec3d velocity;     // sum k_i v_i

  void add(double k, Vec3d offset_to_particle, double particle_radius, Vec3d particle_velocity) {
    weight += k;
    offset += k * offset_to_particle;
    radius += k * particle_radius;
    velocity += k * particle_velocity;
  }
};

// The weighted averages of Eq. 19 at x. Without particles within R the
// weights are undefined (0/0) and `near_liquid` is false.
struct LocalFluid {
  bool near_liquid = false;
  Vec3d mean_offset;    // xbar - x
  double mean_radius = 0;  // rbar
  Vec3d mean_velocity;     // vbar
};

LocalFluid local_fluid(const KernelSums& sums);

// phi of Eq. 19; where no particle lies within R the point is outside and
// phi is R, an upper bound of how far the surface can be from there.
inline double zhu_bridson_distance(const LocalFluid& f, double kernel_radius) {
  return f.near_liquid ? length(f.mean_offset) - f.mean_radius : kernel_radius;
}

// Eq. 19 at single points, for tests and probes; whole grids go through
// sample_liquid_field (liquid_field.h), which gathers the same sums per block.
class ZhuBridsonField {
 public:
  // Keeps references to `particles`, which must outlive the field.
  ZhuBridsonField(const LiquidParticles& particles, double kernel_radius);

  LocalFluid local_fluid(Vec3d x) const;
  double distance(Vec3d x) const { return zhu_bridson_distance(local_fluid(x), kernel_radius_); }

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

}  // namespace dp::mesh
