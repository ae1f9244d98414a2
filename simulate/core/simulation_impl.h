#pragma once
// One simulation step on either backend. Included only by the two
// instantiating files, sim_cpu.cpp and sim_cuda.cu.
#include <cmath>
#include <sstream>
#include <utility>

#include "simulation.h"
#include "sph/particle_grid.h"
#include "sph/wcsph.h"

namespace dp {

// True where a particle's state is not finite, outside the domain, or too fast.
struct IsUnstable {
  const Vec3* position;
  const Vec3* velocity;
  Vec3 lo, hi;
  float max_speed2;
  DP_HD bool operator()(std::size_t i) const {
    Vec3 x = position[i], v = velocity[i];
    bool finite = isfinite(x.x) && isfinite(x.y) && isfinite(x.z) && isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
    if (!finite) return true;
    bool inside = x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
    return !inside || length_squared(v) > max_speed2;
  }
};

template <class Exec>
class SimulationImpl final : public Simulation {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  SimulationImpl(Exec exec, const SimulationSetup& setup) : exec_(std::move(exec)), setup_(setup) {
    const auto& liq = setup.liquid;
    params_.kernel = CubicSplineKernel::with_support(setup.support_radius());
    params_.particle_mass = setup.particle_mass();
    params_.rest_density = liq.rest_density;
    params_.speed_of_sound = liq.speed_of_sound;
    params_.stiffness = liq.rest_density * liq.speed_of_sound * liq.speed_of_sound / 7.0f;
    params_.viscosity_alpha = liq.viscosity_alpha;
    params_.boundary_friction = liq.boundary_friction;
    params_.gravity = setup.gravity;

    UniformGrid grid;
    grid.origin = setup.domain_min;
    grid.cell_size = setup.support_radius();
    Vec3 extent = setup.domain_max - setup.domain_min;
    grid.nx = static_cast<int>(std::ceil(extent.x / grid.cell_size)) + 1;
    grid.ny = static_cast<int>(std::ceil(extent.y / grid.cell_size)) + 1;
    grid.nz = static_cast<int>(std::ceil(extent.z / grid.cell_size)) + 1;
    liquid_grid_.grid = grid;
    rigid_grid_.grid = grid;

    std::size_t n = setup.liquid_position.size();
    std::vector<std::uint32_t> ids(n);
    for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::uint32_t>(i);
    Exec::upload(position_, setup.liquid_position);
    Exec::upload(velocity_, setup.liquid_velocity);
    Exec::upload(id_, ids);
    position_tmp_.resize(n);
    velocity_tmp_.resize(n);
    id_tmp_.resize(n);
    density_.resize(n);
    pressure_.resize(n);
    acceleration_.resize(n);
    prepare_rigids(setup.rigid_position);
  }

  void step() override {
    sort_liquid();
    const GridView liquid = liquid_grid_.view(position_);
    const GridView rigid = rigid_grid_.view(rigid_position_);
    const std::size_t n = position_.size();
    exec_.parallel_for(n, ComputeDensityAndPressure{liquid, rigid, Exec::ptr(rigid_volume_), params_,
                                                    Exec::ptr(density_), Exec::ptr(pressure_)});
    exec_.parallel_for(n, ComputeAcceleration{liquid, rigid, Exec::ptr(rigid_volume_), Exec::ptr(velocity_),
                                              Exec::ptr(density_), Exec::ptr(pressure_), params_,
                                              Exec::ptr(acceleration_)});
    exec_.parallel_for(n, Integrate{Exec::ptr(acceleration_), setup_.time_step, Exec::ptr(velocity_), Exec::ptr(position_)});
    ++steps_;
    check_stability();
  }

  ParticleSnapshot particles() const override {
    ParticleSnapshot s;
    s.position = Exec::download(position_);
    s.velocity = Exec::download(velocity_);
    s.density = Exec::download(density_);
    s.pressure = Exec::download(pressure_);
    s.id = Exec::download(id_);
    s.weight.assign(s.size(), 1.0f);
    s.temperature.assign(s.size(), setup_.liquid.temperature);
    return s;
  }
  std::vector<Vec3> rigid_particles() const override { return Exec::download(rigid_position_); }
  std::vector<float> rigid_volumes() const override { return Exec::download(rigid_volume_); }
  std::int64_t step_count() const override { return steps_; }
  double time() const override { return static_cast<double>(steps_) * setup_.time_step; }
  std::string backend_name() const override { return Exec::name(); }

 private:
  // Rigids are static: sorted and given their volumes once.
  void prepare_rigids(const std::vector<Vec3>& rigid) {
    Buffer<Vec3> unsorted;
    Exec::upload(unsorted, rigid);
    rigid_grid_.sort(exec_, unsorted);
    rigid_position_.resize(rigid.size());
    exec_.parallel_for(rigid.size(), Gather<Vec3>{Exec::ptr(rigid_grid_.order), Exec::ptr(unsorted), Exec::ptr(rigid_position_)});
    rigid_grid_.find_ranges(exec_);
    rigid_volume_.resize(rigid.size());
    exec_.parallel_for(rigid.size(), ComputeBoundaryVolume{rigid_grid_.view(rigid_position_), params_.kernel,
                                                           Exec::ptr(rigid_volume_)});
  }

  // Sorting the particles themselves (not just an index) keeps neighbours
  // close in memory.
  void sort_liquid() {
    const std::size_t n = position_.size();
    liquid_grid_.sort(exec_, position_);
    const std::uint32_t* order = Exec::ptr(liquid_grid_.order);
    exec_.parallel_for(n, Gather<Vec3>{order, Exec::ptr(position_), Exec::ptr(position_tmp_)});
    exec_.parallel_for(n, Gather<Vec3>{order, Exec::ptr(velocity_), Exec::ptr(velocity_tmp_)});
    exec_.parallel_for(n, Gather<std::uint32_t>{order, Exec::ptr(id_), Exec::ptr(id_tmp_)});
    position_.swap(position_tmp_);
    velocity_.swap(velocity_tmp_);
    id_.swap(id_tmp_);
    liquid_grid_.find_ranges(exec_);
  }

  void check_stability() {
    const std::size_t n = position_.size();
    float vmax = setup_.max_speed;
    std::size_t bad = exec_.find_first(n, IsUnstable{Exec::ptr(position_), Exec::ptr(velocity_), setup_.domain_min,
                                                     setup_.domain_max, vmax * vmax});
    if (bad == n) return;
    Vec3 x = Exec::download(position_)[bad], v = Exec::download(velocity_)[bad];
    std::uint32_t id = Exec::download(id_)[bad];
    std::ostringstream detail;
    std::string quantity;
    bool finite = std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) && std::isfinite(v.x) &&
                  std::isfinite(v.y) && std::isfinite(v.z);
    if (!finite) {
      quantity = "non-finite position or velocity";
    } else if (length(v) > vmax) {
      quantity = "speed";
      detail << "speed " << length(v) << " m/s exceeds the bound " << vmax << " m/s";
    } else {
      quantity = "position";
      detail << "particle left the simulation domain";
    }
    throw InstabilityError(steps_, quantity, id, x, detail.str());
  }

  Exec exec_;
  SimulationSetup setup_;
  WcsphParameters params_{};
  ParticleGrid<Exec> liquid_grid_, rigid_grid_;
  Buffer<Vec3> position_, velocity_, acceleration_, position_tmp_, velocity_tmp_;
  Buffer<std::uint32_t> id_, id_tmp_;
  Buffer<float> density_, pressure_;
  Buffer<Vec3> rigid_position_;
  Buffer<float> rigid_volume_;
  std::int64_t steps_ = 0;
};

}  // namespace dp
