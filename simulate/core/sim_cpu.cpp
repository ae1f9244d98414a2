#include "backend/cpu_exec.h"
#include "simulation_impl.h"

namespace dp {
std::unique_ptr<Simulation> make_cpu_simulation(int threads, CpuIsa isa, const SimulationSetup& setup) {
  return std::make_unique<SimulationImpl<CpuExec>>(CpuExec(resolve_thread_count(threads), isa), setup);
}
}  // namespace dp
