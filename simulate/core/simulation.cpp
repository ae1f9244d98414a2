#include "simulation.h"

#include <sstream>

#include "air/air_cell_size.h"

namespace dp {

std::unique_ptr<Simulation> make_cpu_simulation(int threads, CpuIsa isa, const SimulationSetup& setup);
std::unique_ptr<Simulation> make_cuda_simulation(const SimulationSetup& setup);

namespace {
std::string describe_instability(std::int64_t step, const std::string& quantity, std::uint32_t id, Vec3 x,
                                 const std::string& detail) {
  std::ostringstream s;
  s << "simulation unstable at step " << step << ": " << quantity << " of liquid particle id " << id << " at ("
    << x.x << ", " << x.y << ", " << x.z << ") m";
  if (!detail.empty()) s << "; " << detail;
  return s.str();
}
}  // namespace

InstabilityError::InstabilityError(std::int64_t step_, std::string quantity_, std::uint32_t id, Vec3 where_,
                                   const std::string& detail)
    : std::runtime_error(describe_instability(step_, quantity_, id, where_, detail)),
      step(step_),
      quantity(std::move(quantity_)),
      particle_id(id),
      where(where_) {}

InstabilityError::InstabilityError(std::int64_t step_, std::string quantity_, const std::string& location)
    : std::runtime_error("simulation unstable at step " + std::to_string(step_) + ": " + quantity_ + " is not finite in " + location),
      step(step_),
      quantity(std::move(quantity_)),
      particle_id(0),
      where() {}

std::unique_ptr<Simulation> make_simulation(const ExecutionConfig& exec, const SimulationSetup& setup) {
  check_air_cell_size(setup);
  if (exec.device == Device::Cuda) {
    std::string why;
    if (cuda_device_count(&why) == 0) throw std::runtime_error("--device cuda: " + why);
    return make_cuda_simulation(setup);
  }
  return make_cpu_simulation(exec.threads, exec.cpu_isa, setup);
}

}  // namespace dp
