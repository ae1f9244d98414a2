#pragma once
// Rigid boundary particles, Akinci et al. 2012 "Versatile Rigid-Fluid
// Coupling for Incompressible SPH": one layer of particles on each rigid
// surface; each carries the volume it represents, so that unevenly sampled
// surfaces push back evenly.
#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/uniform_grid.h"

namespace dp {

// Akinci 2012, Eq. 4: V_b = 1 / sum_k W_bk over boundary neighbours k
// (itself included). The boundary's contribution to a liquid particle's
// density is then Psi_b W_ib with Psi_b = rho0 V_b (Eq. 5-6).
struct ComputeBoundaryVolume {
  GridView rigid;
  CubicSplineKernel kernel;
  float* volume;
  DP_HD void operator()(std::size_t b) const {
    const Vec3 xb = rigid.position[b];
    const float h2 = kernel.h * kernel.h;
    float sum = 0.0f;
    rigid.for_each_near(xb, [&](std::uint32_t k) {
      float r2 = length_squared(xb - rigid.position[k]);
      if (r2 < h2) sum += kernel.W(sqrtf(r2));
    });
    volume[b] = 1.0f / sum;
  }
};

}  // namespace dp
