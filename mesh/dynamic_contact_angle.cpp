#include "dynamic_contact_angle.h"

#include <algorithm>
#include <cmath>

namespace dp::mesh {

double DynamicContactAngle_HochstetterKolb2017::receding_angle(double speed) const {
  return M_PI / 2 - p_.receding * std::cbrt(speed);
}

double DynamicContactAngle_HochstetterKolb2017::advancing_angle(double speed) const {
  return M_PI / 2 + p_.advancing * std::cbrt(speed);
}

double DynamicContactAngle_HochstetterKolb2017::direction_along_velocity(Vec3d x_p, Vec3d xbar_p, Vec3d velocity) {
  const Vec3d offset = x_p - xbar_p;
  const double norms = length(offset) * length(velocity);
  if (!(norms > 0)) return 0;
  return std::clamp(dot(offset, velocity) / norms, -1.0, 1.0);
}

double DynamicContactAngle_HochstetterKolb2017::angle(double p, double speed) const {
  if (p < 0) {
    const double w = p * p * p * p;
    return w * receding_angle(speed) + (1 - w) * p_.base;
  }
  const double w = std::sqrt(std::sqrt(p));
  return w * advancing_angle(speed) + (1 - w) * p_.base;
}

double DynamicContactAngle_HochstetterKolb2017::angle_at(Vec3d x_p, Vec3d xbar_p, Vec3d velocity) const {
  // One degree short of either end: at 0 or pi the meniscus of Eq. 20 is undefined.
  constexpr double kMargin = M_PI / 180;
  const double alpha = angle(direction_along_velocity(x_p, xbar_p, velocity), length(velocity));
  return std::clamp(alpha, kMargin, M_PI - kMargin);
}

}  // namespace dp::mesh
