// Linked when the CUDA backend is not built; make_simulation reports the
// reason before ever calling this.
#include <stdexcept>

#include "simulation.h"

namespace dp {
std::unique_ptr<Simulation> make_cuda_simulation(const SimulationSetup&) {
  throw std::runtime_error("this dewpoint was built without the CUDA backend");
}
}  // namespace dp
