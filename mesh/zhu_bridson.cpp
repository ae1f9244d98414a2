#include "zhu_bridson.h"

#include "sample_grid.h"

namespace dp::mesh {

ZhuBridsonField::ZhuBridsonField(const LiquidParticles& particles, double kernel_radius)
    : particles_(particles), kernel_radius_(kernel_radius), neighbours_(particles.position, kernel_radius) {}

double ZhuBridsonField::distance(Vec3d x) const {
  const double inverse_r2 = 1.0 / (kernel_radius_ * kernel_radius_);
  double weight_sum = 0, radius_sum = 0;
  Vec3d offset_sum;  // sum of k_i (x_i - x): xbar - x without cancelling large coordinates
  neighbours_.for_each_neighbour(x, [&](std::uint32_t i, Vec3d offset, double distance_squared) {
    const double k = zhu_bridson_kernel(distance_squared * inverse_r2);
    weight_sum += k;
    radius_sum += k * particles_.radius[i];
    offset_sum += k * offset;
  });
  if (!(weight_sum > 0)) return kernel_radius_;
  return (length(offset_sum) - radius_sum) / weight_sum;
}

GridBox zhu_bridson_grid_box(const LiquidParticles& particles, double kernel_radius, double voxel_size) {
  Vec3d lo, hi;
  particle_bounds(particles, lo, hi);
  return covering_grid(lo, hi, voxel_size, kernel_radius + 2 * voxel_size);
}

ScalarGrid sample_zhu_bridson(const LiquidParticles& particles, double kernel_radius, const GridBox& box) {
  const ZhuBridsonField field(particles, kernel_radius);
  return sample_grid(box, [&](Vec3d x) { return field.distance(x); });
}

}  // namespace dp::mesh
