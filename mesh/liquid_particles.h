#pragma once
// The liquid particles of one frame as the mesher needs them: where they are
// and how large each one is.
#include <vector>

#include "ply.h"
#include "vec3d.h"

namespace dp::mesh {

struct LiquidParticles {
  std::vector<Vec3d> position;
  std::vector<double> radius;  // r_i of paper Eq. 19
  std::vector<Vec3d> velocity;  // for the dynamic contact angles of Eq. 22-23; empty: all at rest

  std::size_t size() const { return position.size(); }
};

// Particles from a particle PLY (x, y, z and optionally weight and vx, vy,
// vz). A particle of mass weight w has r_i = nominal_radius * w^(1/3): its
// volume follows its mass (paper Sec. 4.1). Without a weight property every
// w is 1; without velocities every particle is at rest.
// Throws std::runtime_error on missing coordinates or non-finite values.
LiquidParticles liquid_particles_from_ply(const io::PlyData& ply, double nominal_radius);

// Smallest and largest coordinates; both zero when there are no particles.
void particle_bounds(const LiquidParticles& particles, Vec3d& lo, Vec3d& hi);

}  // namespace dp::mesh
