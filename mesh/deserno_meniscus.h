#pragma once
// The meniscus at a vertical wall, Deserno (2004), "Notes on differential
// geometry", as paper Eq. 20 writes it: with arc length s along the liquid
// surface from the wall, capillary length l and psi0 the angle between the
// horizontal and the surface at the wall,
//   x(s) = l [ (s/l) cosh(s/l) + ((s/l) cos(psi0/2) - (1 - cos psi0)) sinh(s/l) ]
//            / [ cosh(s/l) + cos(psi0/2) sinh(s/l) ]
//   y(s) = l 2 sin(psi0/2) / [ cosh(s/l) + cos(psi0/2) sinh(s/l) ],
// x the distance from the wall and y the height above the far level.
// Negative psi0 mirrors the curve (y < 0): a depressed, non-wetting meniscus.
namespace dp::mesh {

class DesernoMeniscus2004 {
 public:
  DesernoMeniscus2004(double psi0, double capillary_length);

  double x(double s) const;  // Eq. 20, distance from the wall
  double y(double s) const;  // Eq. 20, height

  // The height at distance `distance` from the wall: y(s) with x(s) =
  // distance solved for s (x is strictly increasing for |psi0| < pi/2).
  // The paper takes s = distance; see docs/paper-map.md's departures.
  double height_at_distance(double distance) const;

 private:
  double psi0_, l_, cos_half_, sin_half_, cos_;
};

}  // namespace dp::mesh
