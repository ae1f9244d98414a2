#include "zhu_bridson.h"

namespace dp::mesh {

LocalFluid local_fluid(const KernelSums& sums) {
  LocalFluid f;
  if (!(sums.weight > 0)) return f;
  const double inverse = 1.0 / sums.weight;
  f.near_liquid = true;
  f.mean_offset = inverse * sums.offset;
  f.mean_radius = inverse * sums.radius;
  f.mean_velocity = inverse * sums.velocity;
  return f;
}

ZhuBridsonField::ZhuBridsonField(const LiquidParticles& particles, double kernel_radius)
    : particles_(particles), kernel_radius_(kernel_radius), neighbours_(particles.position, kernel_radius) {}

LocalFluid ZhuBridsonField::local_fluid(Vec3d x) const {
  const double inverse_r2 = 1.0 / (kernel_radius_ * kernel_radius_);
  const bool moving = !particles_.velocity.empty();
  KernelSums sums;
  neighbours_.for_each_neighbour(x, [&](std::uint32_t i, Vec3d offset, double distance_squared) {
    sums.add(zhu_bridson_kernel(distance_squared * inverse_r2), offset, particles_.radius[i],
             moving ? particles_.velocity[i] : Vec3d{});
  });
  return mesh::local_fluid(sums);
}

GridBox zhu_bridson_grid_box(const LiquidParticles& particles, double kernel_radius, double voxel_size) {
  Vec3d lo, hi;
  particle_bounds(particles, lo, hi);
  return covering_grid(lo, hi, voxel_size, kernel_radius + 2 * voxel_size);
}

}  // namespace dp::mesh
