#include "adaptivity_cpu_reference.h"

#include "backend/cpu_exec.h"

namespace dp::test {

CpuReference adapt_on_cpu(const HostParticles& start, const UniformGrid& grid, const AdaptivityParameters& params) {
  CpuExec exec(2);
  auto particles = to_device<CpuExec>(start);
  CpuReference r;
  r.result = adapt_particle_masses(exec, particles, grid, params);
  r.particles = to_host(particles);
  return r;
}

}  // namespace dp::test
