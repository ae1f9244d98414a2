#pragma once
// Cubic B-spline kernel (Monaghan 1992) written with its support radius h:
// W(r) = 0 for r >= h. Normalised in 3D: sigma = 8 / (pi h^3).
#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

struct CubicSplineKernel {
  float h;      // support radius
  float sigma;  // 8 / (pi h^3)

  DP_HD static CubicSplineKernel with_support(float h) {
    return CubicSplineKernel{h, 8.0f / (3.14159265358979f * h * h * h)};
  }

  DP_HD float W(float r) const {
    float q = r / h;
    if (q >= 1.0f) return 0.0f;
    if (q <= 0.5f) return sigma * (6.0f * q * q * q - 6.0f * q * q + 1.0f);
    float t = 1.0f - q;
    return sigma * 2.0f * t * t * t;
  }

  // gradW(d) = gradient_factor(d) * d: the scalar part of the gradient, 0
  // outside the support and at d = 0. Neighbour lists fixed for a step keep
  // it per pair (ComputeGradientFactors) for the passes that repeat.
  DP_HD float gradient_factor(Vec3 d) const {
    float r = length(d);
    float q = r / h;
    if (q >= 1.0f || r <= 1e-9f * h) return 0.0f;
    float dWdq;
    if (q <= 0.5f)
      dWdq = sigma * (18.0f * q * q - 12.0f * q);
    else {
      float t = 1.0f - q;
      dWdq = -6.0f * sigma * t * t;
    }
    return dWdq / (h * r);
  }

  // Gradient with respect to x_i of W(|x_i - x_j|), for d = x_i - x_j.
  DP_HD Vec3 gradW(Vec3 d) const { return gradient_factor(d) * d; }
};

}  // namespace dp
