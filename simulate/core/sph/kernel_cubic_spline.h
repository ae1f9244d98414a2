#pragma once
// Cubic B-spline kernel (Monaghan 1992) written with its support radius h:
// W(r) = 0 for r >= h. Normalised in 3D: sigma = 8 / (pi h^3).
#include "backend/host_device.h"
#include "math/keep_if.h"
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
    if (q <= 0.5f) return W_inner(q);
    return W_outer(q);
  }

  // W with both pieces computed and one selected on their bits: the same
  // value, for loops that vectorise (ListedDensity::split_sum).
  DP_HD float W_selected(float r) const {
    const float q = r / h;
    return keep_if(pick_if(q <= 0.5f, W_inner(q), W_outer(q)), q < 1.0f);
  }

  DP_HD float W_inner(float q) const { return sigma * (6.0f * q * q * q - 6.0f * q * q + 1.0f); }  // q <= 1/2
  DP_HD float W_outer(float q) const {  // 1/2 < q < 1
    const float t = 1.0f - q;
    return sigma * 2.0f * t * t * t;
  }

  // gradW(d) = gradient_factor(d) * d: the scalar part of the gradient, 0
  // outside the support and at d = 0. Neighbour lists fixed for a step keep
  // it per pair (ComputeGradientFactors) for the passes that repeat.
  DP_HD float gradient_factor(Vec3 d) const { return gradient_factor_at(length(d)); }

  // The same at distance r. Both pieces are computed and one selected on
  // their bits (keep_if.h): a new list's pairs fall on either side of
  // q = 1/2 at random, and the branch g++ makes of a plain `?:` was
  // mispredicted on every particle (FillListChunks). W keeps
  // its branches for loops that take one pair at a time: in a liquid at
  // rest nearly every pair takes the outer piece, so there the branch is
  // predicted, and computing both pieces cost a settled glass's pressure
  // solve 9 % (docs/benchmarks.md).
  DP_HD float gradient_factor_at(float r) const {
    const float q = r / h;
    const float t = 1.0f - q;
    const float inner = sigma * (18.0f * q * q - 12.0f * q);
    const float outer = -6.0f * sigma * t * t;
    const float factor = pick_if(q <= 0.5f, inner, outer) / (h * r);
    return keep_if(factor, (q < 1.0f) & (r > 1e-9f * h));
  }

  // Gradient with respect to x_i of W(|x_i - x_j|), for d = x_i - x_j.
  DP_HD Vec3 gradW(Vec3 d) const { return gradient_factor(d) * d; }
};

}  // namespace dp
