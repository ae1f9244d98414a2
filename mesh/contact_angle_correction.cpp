#include "contact_angle_correction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "deserno_meniscus.h"

namespace dp::mesh {

ContactAngleCorrection_HochstetterKolb2017::ContactAngleCorrection_HochstetterKolb2017(const RigidWalls& walls,
                                                                                       ContactAngleSettings settings)
    : walls_(walls),
      settings_(std::move(settings)),
      outside_band_(std::hypot(settings_.reach_factor, 1 + std::sqrt(2.0)) - 1 + 0.05) {
  if (settings_.per_rigid.size() != walls.rigid_count())
    throw std::invalid_argument("contact angles: one set of parameters per rigid is needed");
  for (const auto& p : settings_.per_rigid) angles_.emplace_back(p);
}

WallPoint ContactAngleCorrection_HochstetterKolb2017::fluid_wall(Vec3d x, const LocalFluid& f, double phi0,
                                                                 CorrectionCounts& counts, const WallPoint& hint) const {
  if (!f.near_liquid || !may_change_sign(phi0, f.mean_radius)) return {};
  ++counts.considered;
  ++counts.wall_queries;
  return walls_.closest(x + f.mean_offset, settings_.reach_factor * f.mean_radius, &hint);
}

double ContactAngleCorrection_HochstetterKolb2017::corrected_distance(Vec3d x, const LocalFluid& f,
                                                                      const WallPoint& fluid_wall,
                                                                      CorrectionCounts& counts) const {
  ++counts.corrected;
  const double rbar = f.mean_radius;
  const Vec3d xbar = x + f.mean_offset;

  // The wall's normal at xbar_p, facing the fluid: a thin wall may have
  // fluid on either side, whichever way its triangles turn.
  const Vec3d xbar_p = fluid_wall.point;
  Vec3d n = fluid_wall.face_normal;
  if (dot(xbar - xbar_p, n) < 0) n = -n;

  // x_p: the orthogonal projection of x onto the rigid surface. Every wall
  // point is at least as close as xbar_p, which bounds the search.
  ++counts.wall_queries;
  const double x_reach = length(x - xbar_p) * (1 + 1e-9) + 1e-12;
  const WallPoint point_wall = walls_.closest(x, x_reach, &fluid_wall);
  const Vec3d x_p = point_wall.found ? point_wall.point : xbar_p;
  const double wall_distance = point_wall.found ? point_wall.distance : length(x - xbar_p);

  // Eq. 22-24 with the static angle of the rigid the fluid sits on.
  const double alpha = angles_[std::size_t(fluid_wall.rigid)].angle_at(x_p, xbar_p, f.mean_velocity);
  const double d = DesernoMeniscus2004(M_PI / 2 - alpha, rbar).height_at_distance(wall_distance);

  // Eq. 21 with d widening the footprint along the wall (see header).
  const Vec3d to_fluid = f.mean_offset;  // xbar - x
  const double separation = length(to_fluid);
  const double cos_beta = separation > 0 ? std::max(dot(to_fluid, n) / separation, 0.0) : 0.0;
  const double sin_beta = std::sqrt(std::max(0.0, 1 - cos_beta * cos_beta));
  const double footprint_radius = rbar + d;
  double phi;
  if (sin_beta > 1e-12)
    phi = separation - footprint_radius / sin_beta;
  else  // on the axis through xbar along n: inside unless the meniscus has pinched the footprint away
    phi = footprint_radius > 0 ? -separation : separation;

  // Nothing of the liquid behind the wall's tangent plane at xbar_p.
  const double in_front_of_wall = dot(x - xbar_p, n);
  return std::max(phi, -in_front_of_wall);
}

}  // namespace dp::mesh
