#include "liquid_particles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dp::mesh {

LiquidParticles liquid_particles_from_ply(const io::PlyData& ply, double nominal_radius) {
  const std::vector<float> x = ply.floats("x"), y = ply.floats("y"), z = ply.floats("z");
  const bool has_weight = ply.find("weight") != nullptr;
  const std::vector<float> w = has_weight ? ply.floats("weight") : std::vector<float>(ply.vertex_count, 1.0f);
  const bool has_velocity = ply.find("vx") && ply.find("vy") && ply.find("vz");
  const std::vector<float> zero(has_velocity ? 0 : ply.vertex_count, 0.0f);
  const std::vector<float> vx = has_velocity ? ply.floats("vx") : zero, vy = has_velocity ? ply.floats("vy") : zero,
                           vz = has_velocity ? ply.floats("vz") : zero;
  LiquidParticles p;
  p.position.resize(ply.vertex_count);
  p.radius.resize(ply.vertex_count);
  p.velocity.resize(ply.vertex_count);
  for (std::size_t i = 0; i < ply.vertex_count; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i]))
      throw std::runtime_error("particle " + std::to_string(i) + " has a non-finite position");
    // A particle that evaporated to nothing has no extent (w = 0); negative is corrupt.
    if (!std::isfinite(w[i]) || w[i] < 0)
      throw std::runtime_error("particle " + std::to_string(i) + " has weight " + std::to_string(w[i]) +
                               ", expected finite and non-negative");
    if (!std::isfinite(vx[i]) || !std::isfinite(vy[i]) || !std::isfinite(vz[i]))
      throw std::runtime_error("particle " + std::to_string(i) + " has a non-finite velocity");
    p.position[i] = {x[i], y[i], z[i]};
    p.velocity[i] = {vx[i], vy[i], vz[i]};
    p.radius[i] = nominal_radius * std::cbrt(double(w[i]));
  }
  return p;
}

void particle_bounds(const LiquidParticles& particles, Vec3d& lo, Vec3d& hi) {
  lo = hi = Vec3d{};
  if (particles.size() == 0) return;
  lo = hi = particles.position[0];
  for (const Vec3d& x : particles.position)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
}

}  // namespace dp::mesh
