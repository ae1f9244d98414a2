#pragma once
// The two corrections of the Zhu-Bridson distance at rigid walls,
// Hochstetter & Kolb 2017, Sec. 7:
//   footprint (Eq. 21): phi = |x - xbar| - rbar / sin(beta),
//     beta = arccos(max((xbar - x) / |xbar - x| . n, 0)),
//   which extrudes the fluid's footprint towards the wall of normal n, and
//   the meniscus (Eq. 24): d(x) = y(|x_p - x|, pi/2 - alpha(p)) of Deserno's
//   Eq. 20 with capillary length rbar, alpha(p) the dynamic contact angle of
//   Eq. 22-23, added to the footprint radius.
// Applied only where the fluid's mean position is near a wall,
// |xbar - xbar_p| < rbar (times a scene factor, 1 as in the paper).
// Departures (docs/paper-map.md): d widens the footprint along the wall,
// phi = |x - xbar| - (rbar + d) / sin(beta), and y is taken at the arc length
// whose x(s) is |x_p - x|; together these put the mesh's angle at the wall
// on alpha. The liquid is cut off at the wall's tangent plane at xbar_p, so
// the footprint never reaches into or through the rigid.
#include <vector>

#include "dynamic_contact_angle.h"
#include "rigid_walls.h"
#include "zhu_bridson.h"

namespace dp::mesh {

struct ContactAngleSettings {
  std::vector<DynamicContactAngleParameters> per_rigid;  // indexed like the walls' rigids
  double reach_factor = 1;  // correct where |xbar - xbar_p| < reach_factor * rbar
};

// Work done, summed over a grid.
struct CorrectionCounts {
  std::size_t considered = 0;  // nodes near liquid and walls within the band that a correction can change
  std::size_t corrected = 0;   // of those, nodes whose fluid is near a wall (|xbar - xbar_p| < reach)
  std::size_t wall_queries = 0;

  CorrectionCounts& operator+=(const CorrectionCounts& o) {
    considered += o.considered;
    corrected += o.corrected;
    wall_queries += o.wall_queries;
    return *this;
  }
};

class ContactAngleCorrection_HochstetterKolb2017 {
 public:
  // Keeps a reference to `walls`, which must outlive the correction.
  ContactAngleCorrection_HochstetterKolb2017(const RigidWalls& walls, ContactAngleSettings settings);

  // The wall point xbar_p within reach of the fluid's mean position xbar
  // at x, from the local averages f and the uncorrected phi0 = |x - xbar| -
  // rbar of Eq. 19; found = false where no wall is within reach or where no
  // correction can change the sign of phi (phi0 then stands). `hint`, a
  // wall point found at a nearby node, only speeds up the search.
  WallPoint fluid_wall(Vec3d x, const LocalFluid& f, double phi0, CorrectionCounts& counts,
                       const WallPoint& hint) const;

  // phi at x after both corrections, where fluid_wall() found xbar_p; only
  // here is f's mean velocity needed.
  double corrected_distance(Vec3d x, const LocalFluid& f, const WallPoint& fluid_wall, CorrectionCounts& counts) const;

  // Whether any correction can change the sign of phi at a node with this
  // phi0 and rbar. Outside this band the corrections are skipped: the sign
  // is all marching cubes needs there. Inside the liquid the meniscus raises
  // phi by at most |d| <= sqrt(2) rbar (Eq. 20 at s = 0); outside, the
  // footprint reaches at most sqrt(reach^2 + (1 + sqrt 2)^2) rbar from xbar.
  // (A footprint pinched away by alpha > 150 degrees, rbar + d < 0, can
  // raise phi further; deep inside the liquid that is ignored.)
  bool may_change_sign(double phi0, double rbar) const {
    return phi0 > -1.5 * rbar && phi0 < outside_band_ * rbar;
  }

  // Whether a wall can be within reach of xbar, given a lower bound of
  // xbar's distance to every wall (the walls' distance is 1-Lipschitz, so a
  // distance known at one point bounds it at xbar). Only then can the
  // query in fluid_wall() find a wall: skipping the rest changes nothing.
  bool wall_within_reach(double xbar_wall_gap, double rbar) const {
    return xbar_wall_gap < (settings_.reach_factor + 1e-6) * rbar;  // the margin covers rounding
  }

  // How far from xbar a wall is looked for: reach * rbar.
  double fluid_reach(double rbar) const { return settings_.reach_factor * rbar; }

  // How far from x a wall can be and still matter at x: xbar lies within
  // the kernel radius of x, and the wall within reach of xbar.
  double wall_reach(double kernel_radius, double largest_radius) const {
    return kernel_radius + settings_.reach_factor * largest_radius;
  }

  const RigidWalls& walls() const { return walls_; }

 private:
  const RigidWalls& walls_;
  ContactAngleSettings settings_;
  double outside_band_;
  std::vector<DynamicContactAngle_HochstetterKolb2017> angles_;
};

}  // namespace dp::mesh
