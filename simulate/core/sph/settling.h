#pragma once
// Settling the liquid before the first step (SettleSettings): velocities
// decay as dv/dt = -damping v, taken implicitly so that any step is stable.
#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

inline float settling_damping_factor(float damping, float dt) { return 1.0f / (1.0f + damping * dt); }

struct DampVelocity {
  float factor;
  Vec3* velocity;
  DP_HD void operator()(std::size_t i) const { velocity[i] = factor * velocity[i]; }
};

}  // namespace dp
