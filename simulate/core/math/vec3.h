#pragma once
// A 3-vector usable in CUDA kernels and on the host. Written here rather than
// taken from Eigen because kernels pass it by value in device buffers and
// need it trivially copyable, and Eigen's device support costs build time
// and warnings under nvcc; host-side geometry code uses Eigen.
#include <cmath>

#include "backend/host_device.h"

namespace dp {

struct Vec3 {
  float x = 0, y = 0, z = 0;
  DP_HD float operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

DP_HD inline Vec3 make_vec3(float x, float y, float z) { return Vec3{x, y, z}; }
DP_HD inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
DP_HD inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
DP_HD inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
DP_HD inline Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
DP_HD inline Vec3 operator*(Vec3 a, float s) { return {s * a.x, s * a.y, s * a.z}; }
DP_HD inline Vec3& operator+=(Vec3& a, Vec3 b) { a.x += b.x; a.y += b.y; a.z += b.z; return a; }
DP_HD inline Vec3& operator-=(Vec3& a, Vec3 b) { a.x -= b.x; a.y -= b.y; a.z -= b.z; return a; }
DP_HD inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
DP_HD inline float length_squared(Vec3 a) { return dot(a, a); }
DP_HD inline float length(Vec3 a) { return sqrtf(dot(a, a)); }
DP_HD inline Vec3 normalize(Vec3 a) { return (1.0f / length(a)) * a; }
DP_HD inline float max_abs_component(Vec3 a) {
  float m = fabsf(a.x) > fabsf(a.y) ? fabsf(a.x) : fabsf(a.y);
  return m > fabsf(a.z) ? m : fabsf(a.z);
}
DP_HD inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace dp
