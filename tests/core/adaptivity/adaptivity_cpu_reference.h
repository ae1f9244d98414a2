#pragma once
// The CPU result of one adaptivity call, compiled by the host compiler: the
// CPU backend needs OpenMP, which nvcc-compiled files do not get.
#include "adaptivity_clouds.h"

namespace dp::test {

struct CpuReference {
  HostParticles particles;
  AdaptivityResult result;
};

CpuReference adapt_on_cpu(const HostParticles& start, const UniformGrid& grid, const AdaptivityParameters& params);

}  // namespace dp::test
