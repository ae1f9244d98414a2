#pragma once
// Time-step limits: the CFL condition on the fastest particle and the
// force condition on the largest acceleration (Monaghan 1992; as used for
// PCISPH by Solenthaler & Pajarola 2009, Sec. 4).
#include <cmath>

#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

struct SpeedOf {
  const Vec3* velocity;
  DP_HD float operator()(std::size_t i) const { return length(velocity[i]); }
};

struct MagnitudeOf {
  const Vec3* vector;
  DP_HD float operator()(std::size_t i) const { return length(vector[i]); }
};

inline float cfl_time_step(float spacing, float max_speed, float max_acceleration, float cfl_number,
                           float force_number, float max_step) {
  float dt = max_step;
  if (max_speed > 0) dt = std::fmin(dt, cfl_number * spacing / max_speed);
  if (max_acceleration > 0) dt = std::fmin(dt, force_number * std::sqrt(spacing / max_acceleration));
  return dt;
}

}  // namespace dp
