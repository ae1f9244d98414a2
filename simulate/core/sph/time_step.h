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

// PCISPH converges only for steps short enough for the liquid it solves (a
// deep column needs more iterations per step the longer the step), and the
// CFL and force conditions do not see that. A step whose pressure solve
// reaches the iteration cap above eta is solved again at half the length
// (Ihmsen et al. 2010 likewise adapt the step to the solver's density
// error); this limit then remembers the step that converged and lets later
// steps lengthen again by a twentieth per converged step, so that a solve
// that fails costs one wasted solve in about fifteen steps, not every step.
struct ConvergedStepLimit {
  static constexpr float kNone = 1e30f;
  static constexpr float kGrowth = 1.05f;
  float limit = kNone;  // s

  float bound(float dt) const { return std::fmin(dt, limit); }
  void halved_to(float dt) { limit = dt; }
  void converged() {
    if (limit < kNone) limit = std::fmin(limit * kGrowth, kNone);
  }
};

}  // namespace dp
