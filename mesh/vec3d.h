#pragma once
// Double-precision 3-vector for the mesher. The simulator's dp::Vec3 is
// float for the GPU; distances and interpolation here run in double so that
// the surface does not depend on float rounding of large world coordinates.
#include <cmath>

namespace dp::mesh {

struct Vec3d {
  double x = 0, y = 0, z = 0;

  double operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
  double& operator[](int axis) { return axis == 0 ? x : axis == 1 ? y : z; }
};

inline Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3d operator-(Vec3d a) { return {-a.x, -a.y, -a.z}; }
inline Vec3d operator*(double s, Vec3d a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3d operator*(Vec3d a, double s) { return s * a; }
inline Vec3d& operator+=(Vec3d& a, Vec3d b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
inline double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length_squared(Vec3d a) { return dot(a, a); }
inline double length(Vec3d a) { return std::sqrt(dot(a, a)); }
inline Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
// The zero vector stays zero: a flat spot of the field has no direction.
inline Vec3d normalized(Vec3d a) {
  const double n = length(a);
  return n > 0 ? (1.0 / n) * a : Vec3d{};
}

}  // namespace dp::mesh
