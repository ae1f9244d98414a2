#pragma once
// Dynamic contact angles, Hochstetter & Kolb 2017, Sec. 7, Eq. 22-23:
//   alpha_rec(v) = pi/2 - A_rec |v|^(1/3),  alpha_adv(v) = pi/2 + A_adv |v|^(1/3)   (Eq. 22,
//   after Kister 1993: the capillary number goes with the cube of the dynamic angle),
// and between the static angle alpha_base and those, by where the evaluation
// point's wall projection x_p lies relative to the fluid's, xbar_p, along v:
//   p = (x_p - xbar_p) . v / (|x_p - xbar_p| |v|),
//   alpha(p) = p^4 alpha_rec + (1 - p^4) alpha_base        for -1 <= p < 0,
//            = p^(1/4) alpha_adv + (1 - p^(1/4)) alpha_base  for 0 <= p <= 1   (Eq. 23).
// Angles in radians, measured through the liquid.
#include "vec3d.h"

namespace dp::mesh {

struct DynamicContactAngleParameters {
  double base = M_PI / 2;  // alpha_base, the static angle of the wall's material
  double advancing = 0;    // A_adv, radians per (m/s)^(1/3)
  double receding = 0;     // A_rec, radians per (m/s)^(1/3)
};

class DynamicContactAngle_HochstetterKolb2017 {
 public:
  explicit DynamicContactAngle_HochstetterKolb2017(DynamicContactAngleParameters parameters) : p_(parameters) {}

  double receding_angle(double speed) const;   // Eq. 22
  double advancing_angle(double speed) const;  // Eq. 22
  // p of Eq. 23; 0 where the direction is undefined (no motion, or x_p = xbar_p).
  static double direction_along_velocity(Vec3d x_p, Vec3d xbar_p, Vec3d velocity);
  double angle(double p, double speed) const;  // Eq. 23

  // alpha(p) for an evaluation point, kept inside (0, pi) where a fast flow
  // would drive Eq. 22 past the range of a contact angle.
  double angle_at(Vec3d x_p, Vec3d xbar_p, Vec3d velocity) const;

 private:
  DynamicContactAngleParameters p_;
};

}  // namespace dp::mesh
