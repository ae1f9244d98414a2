#include "backend/cuda_exec.cuh"
#include "simulation_impl.h"

namespace dp {
std::unique_ptr<Simulation> make_cuda_simulation(const SimulationSetup& setup) {
  return std::make_unique<SimulationImpl<CudaExec>>(CudaExec(0), setup);
}
}  // namespace dp
