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

// Which rule set a step's length, for the logs.
enum class StepLimit { MaxStep, Speed, Force, Diffusion, Convergence };

inline const char* step_limit_name(StepLimit l) {
  switch (l) {
    case StepLimit::MaxStep: return "time_step_s";
    case StepLimit::Speed: return "speed";
    case StepLimit::Force: return "force";
    case StepLimit::Diffusion: return "diffusion";
    case StepLimit::Convergence: return "convergence";
  }
  return "";
}

inline float cfl_time_step(float spacing, float max_speed, float max_acceleration, float cfl_number,
                           float force_number, float max_step, StepLimit* limit = nullptr) {
  float dt = max_step;
  StepLimit by = StepLimit::MaxStep;
  if (max_speed > 0 && cfl_number * spacing / max_speed < dt) dt = cfl_number * spacing / max_speed, by = StepLimit::Speed;
  if (max_acceleration > 0 && force_number * std::sqrt(spacing / max_acceleration) < dt)
    dt = force_number * std::sqrt(spacing / max_acceleration), by = StepLimit::Force;
  if (limit) *limit = by;
  return dt;
}

// DFSPH (Bender & Koschier 2017 step by the CFL condition alone): its
// pressure is implicit, so only explicit accelerations a (gravity, surface
// tension, adhesion, viscosity) bound the step beside the speeds. No
// particle may travel more than cfl_number spacings in a step, counting what
// a adds within it: (v + a dt) dt <= cfl s, the positive root of
// a dt^2 + v dt - cfl s = 0. With a = 0 it is the CFL condition; at rest it
// is sqrt(cfl s / a), the force condition with 0.63 for 0.25.
inline float travel_time_step(float spacing, float max_speed, float max_acceleration, float cfl_number, float max_step,
                              StepLimit* limit = nullptr) {
  const float reach = cfl_number * spacing;
  float dt = max_step;
  StepLimit by = StepLimit::MaxStep;
  float travel = max_step;
  if (max_acceleration > 0)
    travel = 2 * reach / (max_speed + std::sqrt(max_speed * max_speed + 4 * max_acceleration * reach));
  else if (max_speed > 0)
    travel = reach / max_speed;
  if (travel < dt) {
    dt = travel;
    by = max_speed * dt >= max_acceleration * dt * dt ? StepLimit::Speed : StepLimit::Force;
  }
  if (limit) *limit = by;
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
