#pragma once
// One simulation step on either backend, reading like Algorithm 1, Phase 1.
// Included only by the two instantiating files, sim_cpu.cpp and sim_cuda.cu.
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

#include "air/air_grid.h"
#include "coupling/air_coupling.h"
#include "coupling/emission_texels_to_particles.h"
#include "coupling/path_force.h"
#include "simulation.h"
#include "sph/adaptivity_winchenbach2017_driver.h"
#include "sph/boundary_akinci2012.h"
#include "sph/density.h"
#include "sph/dfsph_bender2017.h"
#include "sph/heat_cleary_monaghan1999.h"
#include "sph/particle_grid.h"
#include "sph/pcisph_solenthaler2009.h"
#include "sph/settling.h"
#include "sph/surface_area_orthmann2013.h"
#include "sph/surface_tension_akinci2013.h"
#include "sph/time_step.h"
#include "sph/transposed_list.h"
#include "sph/viscosity_morris1997.h"
#include "sph/viscosity_xsph.h"
#include "surface/surface_textures.h"

namespace dp {

DP_HD inline bool inside_box(Vec3 x, Vec3 lo, Vec3 hi) {
  return x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
}

// True where a particle's state is not finite, outside the domain (unless
// leaving it is allowed), or too fast.
struct IsUnstable {
  const Vec3* position;
  const Vec3* velocity;
  Vec3 lo, hi;
  float max_speed2;
  bool may_leave;
  DP_HD bool operator()(std::size_t i) const {
    Vec3 x = position[i], v = velocity[i];
    bool finite = isfinite(x.x) && isfinite(x.y) && isfinite(x.z) && isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
    if (!finite) return true;
    return (!may_leave && !inside_box(x, lo, hi)) || length_squared(v) > max_speed2;
  }
};

// Particles past the domain's box give up their units (they leave the
// shot; the units are counted first, exactly, for the ledger).
struct UnitsOutsideBox {
  const Vec3* position;
  const MassUnits* units;
  Vec3 lo, hi;
  DP_HD double operator()(std::size_t i) const { return inside_box(position[i], lo, hi) ? 0.0 : static_cast<double>(units[i]); }
};
struct CountOutsideBox {
  const Vec3* position;
  Vec3 lo, hi;
  DP_HD double operator()(std::size_t i) const { return inside_box(position[i], lo, hi) ? 0.0 : 1.0; }
};
struct EmptyOutsideBox {
  const Vec3* position;
  Vec3 lo, hi;
  MassUnits* units;
  DP_HD void operator()(std::size_t i) const {
    if (!inside_box(position[i], lo, hi)) units[i] = 0;
  }
};

// Gravity plus the other non-pressure accelerations (surface tension and
// adhesion), when there are any.
struct SetNonPressureAcceleration {
  Vec3 gravity;
  const Vec3* other;  // may be null
  Vec3* acceleration;
  DP_HD void operator()(std::size_t i) const { acceleration[i] = other ? gravity + other[i] : gravity; }
};

struct IsLighterThan {
  const MassUnits* units;
  MassUnits threshold;
  DP_HD bool operator()(std::size_t i) const { return units[i] < threshold; }
};

struct TotalAcceleration {
  const Vec3* a;
  const Vec3* b;
  DP_HD float operator()(std::size_t i) const { return length(a[i] + b[i]); }
};

struct ValueOf {
  const float* v;
  DP_HD float operator()(std::size_t i) const { return v[i]; }
};

template <class Exec>
class SimulationImpl final : public Simulation {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;
  using Clock = std::chrono::steady_clock;

 public:
  SimulationImpl(Exec exec, const SimulationSetup& setup) : exec_(std::move(exec)), setup_(setup) {
    kernel_ = CubicSplineKernel::with_support(setup.support_radius());
    particle_mass_ = setup.particle_mass();
    pcisph_sum_ = pcisph_prototype_sum(kernel_, setup.particle_spacing);

    UniformGrid grid;
    grid.origin = setup.domain_min;
    grid.cell_size = setup.support_radius();
    Vec3 extent = setup.domain_max - setup.domain_min;
    grid.nx = static_cast<int>(std::ceil(extent.x / grid.cell_size)) + 1;
    grid.ny = static_cast<int>(std::ceil(extent.y / grid.cell_size)) + 1;
    grid.nz = static_cast<int>(std::ceil(extent.z / grid.cell_size)) + 1;
    liquid_grid_.grid = grid;
    rigid_grid_.grid = grid;
    adaptivity_ = MassAdaptivity<Exec>(grid);
    adaptivity_params_.search_radius = setup.support_radius();

    const std::size_t n = setup.liquid_position.size();
    std::vector<std::uint32_t> ids(n);
    for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::uint32_t>(i);
    Exec::upload(liquid_.position, setup.liquid_position);
    Exec::upload(liquid_.velocity, setup.liquid_velocity);
    Exec::upload(liquid_.id, ids);
    next_id_ = static_cast<std::uint32_t>(n);
    Exec::upload(liquid_.units, setup.liquid_units.size() == n ? setup.liquid_units
                                                               : std::vector<MassUnits>(n, kFullParticleUnits));
    liquid_.extra_count = 0;
    Exec::upload(liquid_.temperature, setup.liquid_temperature.size() == n ? setup.liquid_temperature
                                                                      : std::vector<float>(n, setup.liquid.temperature));
    resize_scratch(n);
    prepare_rigids(setup);
    surfaces_.prepare(exec_, setup, rigid_grid_.view(rigid_position_), rigid_grid_.order, rigid_volume_, rigid_temperature_);
    path_force_.prepare(surfaces_, rigid_position_.size(), setup.coupling.path_force ? setup.coupling.path_adhesion : 0.0f);
    area_calibration_ = flat_face_area_calibration(kernel_, setup.particle_spacing);
    diffusion_dt_limit_ = std::fmin(heat_time_step_limit_of(setup), viscous_time_step_limit(kernel_, setup.liquid.kinematic_viscosity));
    if (setup.air) {
      air_.emplace(exec_, *setup.air, setup.gravity, rigid_grid_.view(rigid_position_));
      coupling_.prepare(exec_, setup.coupling, *air_, rigid_position_, surfaces_);
    }
    initial_water_ = water_ledger();
  }

  StepReport step() override { return step_with(next_time_step()); }

  // The next step of `remaining` seconds split into equal steps of at most
  // `longest`. Cutting only the last step short can leave a sliver (1.6 us
  // after 1 ms steps), and PCISPH removes the density error left by the
  // previous step within the step it is given: pressures grow as 1/dt^2 and
  // the sliver threw a drop's rim particles off at 5 m/s.
  static float step_towards(double remaining, float longest) {
    const double steps = std::ceil(remaining / static_cast<double>(longest));
    return static_cast<float>(remaining / std::max(steps, 1.0));
  }

  void advance_to(double time, const std::function<void(const StepReport&)>& on_step) override {
    // Steps end on frame times exactly; a remainder below a nanosecond is
    // rounding of earlier steps, not a step.
    while (time - time_ > 1e-9) {
      const StepReport& report = step_with(step_towards(time - time_, next_time_step()));
      if (on_step) on_step(report);
    }
  }

  // Before the first step: the liquid alone, damped, for the scene's
  // settling time; then at rest, with the clock still at zero.
  void settle(const std::function<void(const StepReport&)>& on_step) override {
    const double duration = setup_.settle.duration;
    if (duration <= 0 || settling_steps_ > 0 || steps_ > 0) return;
    double settled_time = 0;
    while (duration - settled_time > 1e-9) {
      const StepReport& report = step_with(step_towards(duration - settled_time, next_time_step()), Phase::Settling);
      settled_time += report.dt;
      if (on_step) on_step(report);
    }
    exec_.parallel_for(liquid_.position.size(), DampVelocity{0.0f, Exec::ptr(liquid_.velocity)});
  }

  ParticleSnapshot particles() const override {
    ParticleSnapshot s;
    s.position = Exec::download(liquid_.position);
    s.velocity = Exec::download(liquid_.velocity);
    s.density = Exec::download(density_);
    s.pressure = Exec::download(pressure_);
    s.id = Exec::download(liquid_.id);
    s.mass_units = Exec::download(liquid_.units);
    s.temperature = Exec::download(liquid_.temperature);
    s.surface_area = Exec::download(surface_area_);
    s.weight.resize(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) s.weight[i] = weight_of(s.mass_units[i]);
    return s;
  }
  std::vector<Vec3> rigid_particles() const override { return Exec::download(rigid_position_); }
  std::vector<float> rigid_volumes() const override { return Exec::download(rigid_volume_); }
  std::vector<float> rigid_temperatures() const override { return Exec::download(rigid_temperature_); }
  std::vector<SurfaceSnapshot> surfaces() const override { return surfaces_.snapshots(); }
  std::int64_t step_count() const override { return steps_; }
  double time() const override { return time_; }
  std::string backend_name() const override { return Exec::name(); }
  const StepReport& last_step() const override { return report_; }
  std::optional<AirSnapshot> air() const override {
    if (!air_) return std::nullopt;
    return air_->snapshot();
  }
  SimulationState state() const override {
    SimulationState s;
    s.steps = steps_;
    s.settling_steps = settling_steps_;
    s.time = time_;
    s.last_max_acceleration = last_max_acceleration_;
    s.converged_step_limit = converged_limit_.limit;
    s.emitted_particles = emitted_particles_;
    s.left_domain_particles = left_domain_particles_;
    s.left_domain_units = left_domain_units_;
    split_units(coupling_.liquid_to_air_units(), s.liquid_to_air_lo, s.liquid_to_air_hi);
    split_units(coupling_.texels_to_air_units(), s.texels_to_air_lo, s.texels_to_air_hi);
    s.initial_water = initial_water_;
    LiquidState& l = s.liquid;
    l.position = Exec::download(liquid_.position);
    l.velocity = Exec::download(liquid_.velocity);
    l.temperature = Exec::download(liquid_.temperature);
    l.mass_units = Exec::download(liquid_.units);
    l.id = Exec::download(liquid_.id);
    l.density = Exec::download(density_);
    l.pressure = Exec::download(pressure_);
    l.surface_area = Exec::download(surface_area_);
    l.next_id = next_id_;
    s.rigid_temperature = Exec::download(rigid_temperature_);
    s.surfaces = surfaces_.states();
    s.has_air = air_.has_value();
    if (air_) s.air = air_->state();
    return s;
  }

  void restore(const SimulationState& s) override {
    const LiquidState& l = s.liquid;
    const std::size_t n = l.position.size();
    const bool liquid_fits = l.velocity.size() == n && l.temperature.size() == n && l.mass_units.size() == n && l.id.size() == n &&
                             l.density.size() == n && l.pressure.size() == n && l.surface_area.size() == n;
    if (!liquid_fits) throw std::invalid_argument("simulation state: liquid particle arrays differ in length");
    if (s.rigid_temperature.size() != rigid_temperature_.size())
      throw std::invalid_argument("simulation state: " + std::to_string(s.rigid_temperature.size()) + " rigid particles, the setup has " +
                                  std::to_string(rigid_temperature_.size()));
    if (s.has_air != air_.has_value()) throw std::invalid_argument("simulation state: the air phase is present in one of state and setup only");
    surfaces_.restore(s.surfaces);
    if (air_) air_->restore(s.air);
    Exec::upload(liquid_.position, l.position);
    Exec::upload(liquid_.velocity, l.velocity);
    Exec::upload(liquid_.temperature, l.temperature);
    Exec::upload(liquid_.units, l.mass_units);
    Exec::upload(liquid_.id, l.id);
    liquid_.extra.resize(0);
    liquid_.extra_count = 0;
    resize_scratch(n);
    Exec::upload(density_, l.density);
    Exec::upload(pressure_, l.pressure);
    Exec::upload(surface_area_, l.surface_area);
    next_id_ = l.next_id;
    Exec::upload(rigid_temperature_, s.rigid_temperature);
    steps_ = s.steps;
    settling_steps_ = s.settling_steps;
    time_ = s.time;
    last_max_acceleration_ = s.last_max_acceleration;
    converged_limit_.limit = s.converged_step_limit;
    emitted_particles_ = s.emitted_particles;
    left_domain_particles_ = s.left_domain_particles;
    left_domain_units_ = s.left_domain_units;
    coupling_.restore_units(join_units(s.liquid_to_air_lo, s.liquid_to_air_hi), join_units(s.texels_to_air_lo, s.texels_to_air_hi));
    initial_water_ = s.initial_water;
    report_ = StepReport{};
  }

  WaterLedger water_ledger() const override {
    WaterLedger l;
    std::uint64_t units = 0;  // exact: 2^24 per particle, far from 2^64
    for (MassUnits u : Exec::download(liquid_.units)) units += u;
    l.liquid_kg = static_cast<double>(units) * (static_cast<double>(particle_mass_) / kFullParticleUnits);
    for (const SurfaceSnapshot& s : surfaces_.snapshots()) l.texel_kg += s.total_mass().kg(s.kg_per_unit);
    l.initial_kg = initial_water_.total_kg();
    if (air_) {
      const AirLedger& a = air_->ledger();
      l.vapor_kg = air_->vapor_mass(exec_);
      l.inflow_gain_kg = a.inflow_gain;
      l.open_in_kg = a.open_in;
      l.open_out_kg = a.open_out;
      const double k = surfaces_.kg_per_unit();
      l.liquid_to_air_kg = static_cast<double>(coupling_.liquid_to_air_units()) * k;
      l.texels_to_air_kg = static_cast<double>(coupling_.texels_to_air_units()) * k;
    }
    l.texels_to_liquid_kg = static_cast<double>(emitted_particles_) * particle_mass_;
    l.liquid_out_kg = static_cast<double>(left_domain_units_) * (static_cast<double>(particle_mass_) / kFullParticleUnits);
    if (steps_ == 0 && l.initial_kg == 0) l.initial_kg = l.total_kg();
    return l;
  }

 private:
  using Units = typename AirCoupling<Exec>::Units;
  static void split_units(Units u, std::uint64_t& lo, std::int64_t& hi) {
    lo = static_cast<std::uint64_t>(u);
    hi = static_cast<std::int64_t>(u >> 64);
  }
  static Units join_units(std::uint64_t lo, std::int64_t hi) {
    __extension__ typedef unsigned __int128 Bits;  // shifting the signed type left is undefined for negative values
    return static_cast<Units>((static_cast<Bits>(static_cast<std::uint64_t>(hi)) << 64) | lo);
  }

  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

  void resize_scratch(std::size_t n) {
    for (auto* b : {&position_tmp_, &velocity_tmp_, &predicted_, &nonpressure_acc_, &pressure_acc_, &normal_, &tension_acc_})
      b->resize(n);
    for (auto* b : {&temperature_tmp_, &mass_, &volume_, &density_, &pressure_, &pressure_start_, &density_error_, &surface_area_,
                    &liquid_rate_, &dfsph_factor_, &stiffness_, &divergence_pressure_})
      b->resize(n);
    id_tmp_.resize(n);
    units_tmp_.resize(n);
  }

  // Rigids are static: sorted and given their volumes once.
  void prepare_rigids(const SimulationSetup& setup) {
    const std::size_t m = setup.rigid_position.size();
    Buffer<Vec3> unsorted;
    Exec::upload(unsorted, setup.rigid_position);
    rigid_grid_.sort(exec_, unsorted);
    const std::uint32_t* order = Exec::ptr(rigid_grid_.order);
    rigid_position_.resize(m);
    exec_.parallel_for(m, Gather<Vec3>{order, Exec::ptr(unsorted), Exec::ptr(rigid_position_)});
    rigid_grid_.find_ranges(exec_);
    rigid_volume_.resize(m);
    exec_.parallel_for(m, ComputeBoundaryVolume{rigid_grid_.view(rigid_position_), kernel_, Exec::ptr(rigid_volume_)});
    // Their neighbourhoods among themselves, and the pairs' gradient
    // factors, hold for the whole run (rigid<->rigid conduction).
    rigid_rigid_pairs_ = rigid_rigid_neighbors_.build_with_gradients(exec_, rigid_position_, rigid_grid_.view(rigid_position_), kernel_);

    Buffer<float> temperature;
    Buffer<std::uint8_t> held;
    Exec::upload(temperature, setup.rigid_temperature.size() == m ? setup.rigid_temperature
                                                                   : std::vector<float>(m, setup.liquid.temperature));
    Exec::upload(held, setup.rigid_held.size() == m ? setup.rigid_held : std::vector<std::uint8_t>(m, 0));
    rigid_temperature_.resize(m);
    rigid_held_.resize(m);
    rigid_rate_.resize(m);
    exec_.parallel_for(m, Gather<float>{order, Exec::ptr(temperature), Exec::ptr(rigid_temperature_)});
    exec_.parallel_for(m, Gather<std::uint8_t>{order, Exec::ptr(held), Exec::ptr(rigid_held_)});

    Buffer<float> adhesion;
    Exec::upload(adhesion, setup.rigid_adhesion.size() == m ? setup.rigid_adhesion : std::vector<float>(m, 0.0f));
    rigid_adhesion_.resize(m);
    exec_.parallel_for(m, Gather<float>{order, Exec::ptr(adhesion), Exec::ptr(rigid_adhesion_)});
    for (float beta : setup.rigid_adhesion) has_adhesion_ = has_adhesion_ || beta > 0;
  }

  // Explicit heat conduction is stable below rho C h^2 / (24 kappa) for each
  // material, kappa being the larger of its own and the harmonic mean with
  // the other material (heat_cleary_monaghan1999.h).
  static float heat_time_step_limit_of(const SimulationSetup& setup) {
    if (!setup.heat_conduction) return 1e30f;
    const CubicSplineKernel kernel = CubicSplineKernel::with_support(setup.support_radius());
    const LiquidMaterial& l = setup.liquid;
    const RigidMaterial& r = setup.rigid;
    const float mixed = l.conductivity + r.conductivity > 0 ? 2 * l.conductivity * r.conductivity / (l.conductivity + r.conductivity) : 0;
    float dt = 1e30f;
    const float kl = std::fmax(l.conductivity, setup.rigid_position.empty() ? 0.0f : mixed);
    if (kl > 0) dt = std::fmin(dt, heat_time_step_limit(kernel, l.rest_density, l.specific_heat, kl));
    const float kr = std::fmax(r.conductivity, mixed);
    if (!setup.rigid_position.empty() && kr > 0) dt = std::fmin(dt, heat_time_step_limit(kernel, r.density, r.specific_heat, kr));
    return dt;
  }

  // Alg. 1 line 4: conduction liquid<->liquid, liquid<->rigid, rigid<->rigid
  // (Cleary & Monaghan 1999, paper Eq. 9), explicit in time.
  void conduct_heat(float dt, const GridView& liquid, const GridView& rigid) {
    const std::size_t n = liquid_.position.size(), m = rigid_position_.size();
    const LiquidMaterial& l = setup_.liquid;
    const RigidMaterial& r = setup_.rigid;
    const ThermalParticles liquid_set = ThermalParticles::liquid(liquid, Exec::ptr(liquid_.temperature), Exec::ptr(mass_),
                                                                 Exec::ptr(volume_), l.conductivity, l.specific_heat);
    const ThermalParticles rigid_set = ThermalParticles::rigid(rigid, Exec::ptr(rigid_temperature_), Exec::ptr(rigid_volume_),
                                                               r.density, r.conductivity, r.specific_heat);
    // Both rates from the temperatures at the start of the step, then both
    // updates: the exchange between the sets stays antisymmetric.
    exec_.parallel_for(n, ComputeTemperatureRate{liquid_set, rigid_set, m > 0, kernel_, Exec::ptr(liquid_rate_), liquid_pairs_,
                                                 rigid_pairs_});
    ComputeTemperatureRate rigid_rate{rigid_set, liquid_set, n > 0, kernel_, Exec::ptr(rigid_rate_), rigid_rigid_pairs_};
    if constexpr (Exec::kBuffersInHostMemory)  // the liquid near each rigid particle, from the liquid's rigid lists
      if (rigid_pairs_.present()) rigid_rate.other_near = liquid_near_rigid_.build(rigid_pairs_.list, n, m);
    exec_.parallel_for(m, rigid_rate);
    exec_.parallel_for(n, IntegrateTemperature{Exec::ptr(liquid_rate_), nullptr, dt, Exec::ptr(liquid_.temperature)});
    exec_.parallel_for(m, IntegrateTemperature{Exec::ptr(rigid_rate_), Exec::ptr(rigid_held_), dt, Exec::ptr(rigid_temperature_)});
  }

  float next_time_step() {
    const TimeStepSettings& ts = setup_.time_step;
    step_limit_ = StepLimit::MaxStep;
    if (ts.mode == TimeStepMode::Fixed) return ts.max_step;
    const std::size_t n = liquid_.position.size();
    float vmax = exec_.max(n, SpeedOf{Exec::ptr(liquid_.velocity)}, 0.0f);
    // The last step's total acceleration bounds the next one's; gravity
    // alone before the first step.
    float amax = length(setup_.gravity);
    if (steps_ > 0 || settling_steps_ > 0) amax = std::fmax(amax, last_max_acceleration_);
    StepLimit by = StepLimit::MaxStep;
    const float longest = std::fmin(ts.max_step, diffusion_dt_limit_);
    const float cfl = dfsph() ? travel_time_step(setup_.particle_spacing, vmax, amax, ts.cfl_number, longest, &by)
                              : cfl_time_step(setup_.particle_spacing, vmax, amax, ts.cfl_number, ts.force_number, longest, &by);
    if (by == StepLimit::MaxStep && diffusion_dt_limit_ < ts.max_step) by = StepLimit::Diffusion;
    const float dt = converged_limit_.bound(cfl);
    if (dt < cfl) by = StepLimit::Convergence;
    step_limit_ = by;
    if (dt < ts.min_step) {
      std::ostringstream s;
      s << "CFL time step " << dt << " s below the minimum " << ts.min_step << " s (max speed " << vmax
        << " m/s, max acceleration " << amax << " m/s^2)";
      throw InstabilityError(steps_ + 1, "time step", 0, Vec3{}, s.str());
    }
    return dt;
  }

  // A step of the whole simulation, or (Settling) of the liquid alone with
  // its velocities damped: no heat, textures, air or evaporation, and the
  // clock stands still (settle).
  enum class Phase { Running, Settling };

  StepReport step_with(float planned_dt, Phase phase = Phase::Running) {
    const bool running = phase == Phase::Running;
    StepReport report;
    report.dt = planned_dt;
    report.limited_by = step_limit_name(step_limit_);
    // Alg. 1 line 18 of the previous step, run here so that the state a
    // frame sees (positions and the step's densities, pressures, areas) is
    // of one particle set.
    // A warm solve reads each particle's pressure from the last step, which
    // merging and removal leave to other particles.
    bool warm = setup_.pressure.warm_start && !dfsph();  // DFSPH solves from zero (sph/dfsph_bender2017.h)
    if (running && remove_leaving_particles(report)) warm = false;
    if (running && adapt_masses()) warm = false;
    auto t0 = Clock::now();
    sort_liquid();  // Alg. 1 line 3
    // The step's neighbourhoods, found once for all pressure iterations.
    liquid_pairs_ = liquid_neighbors_.build_with_gradients(exec_, liquid_.position, liquid_grid_.view(liquid_.position), kernel_);
    rigid_pairs_ = rigid_neighbors_.build_with_gradients(exec_, liquid_.position, rigid_grid_.view(rigid_position_), kernel_);
    exec_.synchronize();
    report.seconds_neighbours = seconds_since(t0);

    auto t1 = Clock::now();
    const std::size_t n = liquid_.position.size();
    const GridView liquid = liquid_grid_.view(liquid_.position);
    const GridView rigid = rigid_grid_.view(rigid_position_);
    exec_.parallel_for(n, ParticleMass{Exec::ptr(liquid_.units), particle_mass_, Exec::ptr(mass_)});
    exec_.parallel_for(n, ComputeDensity{listed_density(Exec::ptr(liquid_.position)), Exec::ptr(density_)});
    exec_.parallel_for(n, ParticleVolume{Exec::ptr(mass_), Exec::ptr(density_), Exec::ptr(volume_)});
    if (dfsph()) {
      exec_.parallel_for(n, ComputeDfsphFactor{listed_particles(), Exec::ptr(dfsph_factor_)});
      solve_divergence(planned_dt, report);
    }
    // The colour gradient serves twice: Akinci 2013's surface normals and
    // the particles' surface areas.
    exec_.parallel_for(n, ComputeSurfaceNormal{liquid, Exec::ptr(liquid_.units), Exec::ptr(density_), kernel_,
                                               particle_mass_, Exec::ptr(normal_), liquid_pairs_});
    exec_.parallel_for(n, ComputeSurfaceArea{liquid, Exec::ptr(liquid_.units), Exec::ptr(density_), particle_mass_, rigid,
                                             Exec::ptr(rigid_volume_), rigid_position_.size() > 0, kernel_,
                                             area_calibration_, Exec::ptr(surface_area_), Exec::ptr(normal_),
                                             liquid_pairs_, rigid_pairs_});
    exec_.synchronize();
    double other = seconds_since(t1);

    t1 = Clock::now();
    // Alg. 1 line 5: external forces; surface tension and adhesion after
    // Akinci et al. 2013.
    const bool tension = setup_.liquid.surface_tension > 0 || has_adhesion_ || path_force_.active();
    if (tension) {
      const SurfaceTensionParameters st{kernel_, particle_mass_, setup_.liquid.rest_density, setup_.liquid.surface_tension};
      exec_.parallel_for(n, ComputeSurfaceTensionAcceleration{liquid, rigid, Exec::ptr(liquid_.units), Exec::ptr(density_),
                                                              Exec::ptr(normal_), Exec::ptr(rigid_volume_),
                                                              Exec::ptr(rigid_adhesion_), st, Exec::ptr(tension_acc_),
                                                              liquid_pairs_, rigid_pairs_});
      // Alg. 1 line 19 (coupling/path_force.h), from the wetting history as
      // the previous step left it: this step's length is known only after
      // the pressure solve.
      path_force_.apply(exec_, surfaces_, rigid, rigid_volume_, Exec::ptr(liquid_.position), n, kernel_.h,
                        setup_.liquid.rest_density, Exec::ptr(tension_acc_));
    }
    exec_.parallel_for(n, SetNonPressureAcceleration{setup_.gravity, tension ? Exec::ptr(tension_acc_) : nullptr,
                                                     Exec::ptr(nonpressure_acc_)});
    if (setup_.liquid.kinematic_viscosity > 0) {
      const bool walls = !rigid_position_.empty();
      exec_.parallel_for(n, AddViscosityMorris1997{liquid, rigid, Exec::ptr(liquid_.units), Exec::ptr(density_),
                                                   walls ? Exec::ptr(rigid_volume_) : nullptr, Exec::ptr(liquid_.velocity),
                                                   kernel_, particle_mass_, setup_.liquid.kinematic_viscosity,
                                                   wall_layer_volume_per_akinci_volume(kernel_, setup_.particle_spacing),
                                                   Exec::ptr(nonpressure_acc_), liquid_pairs_, rigid_pairs_,
                                                   setup_.liquid.wall_shear});
    }
    exec_.synchronize();
    other += seconds_since(t1);

    auto t2 = Clock::now();
    const float dt = solve_pressure_converging(planned_dt, warm ? SolveStart::Warm : SolveStart::Cold, report);  // Alg. 1 line 6
    report.dt = dt;
    exec_.synchronize();
    report.seconds_pressure = seconds_since(t2);

    // Heat and the texels' state from the positions at the start of the
    // step, which the pressure solve has not moved.
    auto th = Clock::now();
    if (running) {
      if (setup_.heat_conduction) conduct_heat(dt, liquid, rigid);
      surfaces_.step(exec_, dt, rigid_temperature_, liquid, n);  // Alg. 1 line 14, wetting history
    }
    exec_.synchronize();
    report.seconds_heat = seconds_since(th);

    auto t3 = Clock::now();
    exec_.parallel_for(n, IntegrateMotion{Exec::ptr(nonpressure_acc_), Exec::ptr(pressure_acc_), dt, Exec::ptr(liquid_.velocity),
                                          Exec::ptr(liquid_.position)});  // Alg. 1 line 2, for the next step
    exec_.parallel_for(n, ApplyXsph{liquid_pairs_.list, rigid_pairs_.list, Exec::ptr(liquid_.position), Exec::ptr(rigid_position_),
                                    Exec::ptr(volume_), Exec::ptr(rigid_volume_), Exec::ptr(liquid_.velocity), kernel_,
                                    setup_.liquid.xsph_epsilon, setup_.liquid.boundary_friction, Exec::ptr(velocity_tmp_)});
    liquid_.velocity.swap(velocity_tmp_);
    if (!running) exec_.parallel_for(n, DampVelocity{settling_damping_factor(setup_.settle.damping, dt), Exec::ptr(liquid_.velocity)});
    // The force condition bounds explicit forces. DFSPH's pressure is implicit
    // and follows the speeds, which the CFL condition bounds already (as in
    // Bender & Koschier 2017); PCISPH keeps the published condition on the
    // total acceleration.
    last_max_acceleration_ = dfsph() ? exec_.max(n, MagnitudeOf{Exec::ptr(nonpressure_acc_)}, 0.0f)
                                     : exec_.max(n, TotalAcceleration{Exec::ptr(nonpressure_acc_), Exec::ptr(pressure_acc_)}, 0.0f);
    if (running) {
      ++steps_;
      time_ += dt;
    } else {
      ++settling_steps_;
    }
    check_stability(phase);
    exec_.synchronize();
    report.seconds_other = other + seconds_since(t3);
    if (!running) return report;
    step_air(dt, report);  // Alg. 1 Phase 2
    couple(dt, report);    // Alg. 1 Phase 3, lines 12-16
    emit_particles();      // line 17
    check_air_stability();
    report_ = report;
    return report;
  }

  // Alg. 1 lines 7-11: cells classified from the particles as they stand
  // after the particle phase, then the air step.
  void step_air(float dt, StepReport& report) {
    if (!air_) return;
    const auto t = Clock::now();
    air_->classify(exec_, ParticlePositions{Exec::ptr(liquid_.position), liquid_.size()});
    report.air = air_->step(exec_, dt);
    exec_.synchronize();
    report.seconds_grid = seconds_since(t);
  }

  // Alg. 1 lines 12-16, the air's side of Phase 3 (texel temperatures,
  // line 14, run with the particles' heat). Line 17 is emit_particles; line
  // 18 runs at the start of the next step (adapt_masses), removing particles
  // that evaporated completely; line 19 (path force) joins the next step's
  // surface tension and adhesion (path_force_, coupling/path_force.h).
  void couple(float dt, StepReport& report) {
    if (!air_) return;
    auto t = Clock::now();
    coupling_.find_neighbours(exec_, *air_, liquid_.position);  // line 12
    exec_.synchronize();
    report.seconds_neighbours += seconds_since(t);
    t = Clock::now();
    const LiquidMaterial& l = setup_.liquid;
    const RigidMaterial& r = setup_.rigid;
    const float spacing = setup_.particle_spacing;
    const HeatSurfels liquid{Exec::ptr(surface_area_), 0.0f, Exec::ptr(liquid_.units), nullptr, particle_mass_, l.specific_heat,
                             l.conductivity, nullptr, Exec::ptr(liquid_.id), Exec::ptr(liquid_.temperature)};
    // A boundary particle stands for one spacing squared of the rigid's surface.
    const HeatSurfels rigid{nullptr, spacing * spacing, nullptr, Exec::ptr(rigid_volume_), r.density, r.specific_heat, r.conductivity,
                            Exec::ptr(rigid_held_), nullptr, Exec::ptr(rigid_temperature_)};
    coupling_.exchange_heat(exec_, *air_, liquid, rigid, dt, static_cast<std::uint64_t>(steps_));  // line 13
    exec_.synchronize();
    report.seconds_heat += seconds_since(t);
    t = Clock::now();
    const double unit_kg = kg_per_texel_unit(particle_mass_);
    coupling_.evaporate_particles(exec_, *air_, surface_area_, liquid_.temperature, liquid_.id, liquid_.units, l.specific_heat,
                                  unit_kg, dt, static_cast<std::uint64_t>(steps_));  // line 15
    coupling_.exchange_texels(exec_, *air_, surfaces_, dt);                                       // line 16
    exec_.synchronize();
    report.seconds_evaporation = seconds_since(t);
  }

  // Alg. 1 line 17 (Sec. 6.2): seeds whose texels hold a particle's mass
  // emit one. Emission is rare, so the new particles are appended on the
  // host, and only in steps where some seed emitted.
  void emit_particles() {
    if (!setup_.coupling.particle_emission) return;
    for (std::size_t r = 0; r < surfaces_.count(); ++r) {
      auto& tex = surfaces_.texture(r);
      const std::size_t seeds = tex.seeds.size();
      if (seeds == 0) continue;
      emitted_.resize(seeds);
      seed_temperature_.resize(seeds);
      exec_.parallel_for(seeds, EmitFromSeeds{Exec::ptr(tex.seed_texel_offset), Exec::ptr(tex.seed_texel_index), Exec::ptr(tex.wetting),
                                              Exec::ptr(tex.temperature), setup_.coupling.wet_threshold, Exec::ptr(tex.mass),
                                              Exec::ptr(emitted_), Exec::ptr(seed_temperature_)});
      if (exec_.find_first(seeds, IsSet{Exec::ptr(emitted_)}) == seeds) continue;
      append_emitted(tex.seeds, Exec::download(emitted_), Exec::download(seed_temperature_));
    }
  }

  void append_emitted(const SeedingPoints& seeds, const std::vector<std::uint8_t>& emitted, const std::vector<float>& temperature) {
    std::vector<Vec3> x = Exec::download(liquid_.position), v = Exec::download(liquid_.velocity);
    std::vector<float> t = Exec::download(liquid_.temperature);
    std::vector<MassUnits> u = Exec::download(liquid_.units);
    std::vector<std::uint32_t> id = Exec::download(liquid_.id);
    for (std::size_t s = 0; s < emitted.size(); ++s) {
      if (!emitted[s]) continue;
      x.push_back(seeds.position[s] + setup_.particle_spacing * seeds.normal[s]);
      v.push_back(Vec3{0, 0, 0});
      t.push_back(temperature[s]);
      u.push_back(kFullParticleUnits);
      id.push_back(next_id_++);
      ++emitted_particles_;
    }
    Exec::upload(liquid_.position, x);
    Exec::upload(liquid_.velocity, v);
    Exec::upload(liquid_.temperature, t);
    Exec::upload(liquid_.units, u);
    Exec::upload(liquid_.id, id);
    resize_scratch(x.size());
  }

  // PCISPH: predict, correct pressures until the average density error is
  // below eta (at least min_iterations, at most max_iterations).
  ListedDensity listed_density(const Vec3* position) const {
    return ListedDensity{liquid_pairs_.list, rigid_pairs_.list, position, Exec::ptr(rigid_position_), Exec::ptr(liquid_.units),
                         Exec::ptr(rigid_volume_), kernel_, particle_mass_, setup_.liquid.rest_density};
  }

  // Alg. 1 line 6 at the planned step or, where PCISPH does not converge
  // within its cap, at the first halving of it that does; after 4 halvings
  // the last solve stands. CFL mode only: a fixed step is the user's.
  float solve_pressure_converging(float dt, SolveStart start, StepReport& report) {
    constexpr int kMaxHalvings = 4;
    // The last step's pressures, kept aside: a halved step starts where the
    // first solve started.
    if (start == SolveStart::Warm) pressure_start_.swap(pressure_);
    bool converged = solve_pressure(dt, start, report);
    int halvings = 0;
    while (!converged && setup_.time_step.mode == TimeStepMode::Cfl && halvings < kMaxHalvings &&
           0.5f * dt >= setup_.time_step.min_step) {
      dt *= 0.5f;
      ++halvings;
      converged = solve_pressure(dt, start, report);
    }
    report.pressure_halvings = halvings;
    if (dfsph()) exec_.parallel_for(liquid_.position.size(), AddDivergencePressure{Exec::ptr(divergence_pressure_), Exec::ptr(pressure_)});
    if (halvings > 0) {
      report.limited_by = step_limit_name(StepLimit::Convergence);
      converged_limit_.halved_to(dt);
    } else if (converged)
      converged_limit_.converged();
    return dt;
  }

  bool dfsph() const { return setup_.pressure.method == PressureSolverMethod::Dfsph; }

  ListedParticles listed_particles() const {
    return ListedParticles{liquid_pairs_, rigid_pairs_, Exec::ptr(liquid_.position), Exec::ptr(rigid_position_),
                          Exec::ptr(mass_), Exec::ptr(rigid_volume_), Exec::ptr(density_), setup_.liquid.rest_density};
  }

  // Bender & Koschier 2017, Alg. 2: the velocities made divergence-free
  // (compression only) before the step's forces, at least one iteration.
  void solve_divergence(float dt, StepReport& report) {
    const std::size_t n = liquid_.position.size();
    const PressureSolverSettings& ps = setup_.pressure;
    const ListedParticles p = listed_particles();
    exec_.parallel_for(n, ClearDivergencePressure{Exec::ptr(divergence_pressure_)});
    int iteration = 0;
    while (iteration < ps.max_iterations) {
      exec_.parallel_for(n, ComputeDivergenceStiffness{p, Exec::ptr(liquid_.velocity), Exec::ptr(dfsph_factor_), dt, kDfsphRelaxation,
                                                       Exec::ptr(stiffness_), Exec::ptr(density_error_)});
      ++iteration;
      if (average_density_error() <= ps.max_divergence_error) break;
      exec_.parallel_for(n, AddStiffnessCorrection{p, Exec::ptr(stiffness_), dt, Exec::ptr(liquid_.velocity),
                                                   Exec::ptr(divergence_pressure_)});
    }
    report.divergence_iterations = iteration;
  }

  // Bender & Koschier 2017, Alg. 3: pressure accelerations that leave the
  // predicted velocities' density error below eta. Returns whether they do.
  bool solve_density_dfsph(float dt, StepReport& report) {
    const std::size_t n = liquid_.position.size();
    const PressureSolverSettings& ps = setup_.pressure;
    const ListedParticles p = listed_particles();
    const AddStiffnessCorrection correct{p, Exec::ptr(stiffness_), 1.0f, Exec::ptr(pressure_acc_), Exec::ptr(pressure_)};
    exec_.parallel_for(n, ClearPressure{Exec::ptr(pressure_), Exec::ptr(pressure_acc_)});
    int iteration = 0;
    float error = 0;
    while (iteration < ps.max_iterations) {
      exec_.parallel_for(n, PredictVelocity{Exec::ptr(liquid_.velocity), Exec::ptr(nonpressure_acc_), Exec::ptr(pressure_acc_), dt,
                                            Exec::ptr(predicted_)});
      exec_.parallel_for(n, ComputeDensityStiffness{p, Exec::ptr(predicted_), Exec::ptr(dfsph_factor_), dt, kDfsphRelaxation,
                                                    Exec::ptr(stiffness_),
                                                    Exec::ptr(density_error_)});
      ++iteration;
      error = average_density_error();
      if (iteration >= ps.min_iterations && error <= ps.max_density_error) break;
      exec_.parallel_for(n, correct);
    }
    report.pressure_iterations = iteration;
    report.density_error = error;
    return error <= ps.max_density_error;
  }

  float average_density_error() const {
    const std::size_t n = liquid_.position.size();
    return n > 0 ? static_cast<float>(exec_.sum(n, ValueOf{Exec::ptr(density_error_)}) / static_cast<double>(n)) : 0.0f;
  }

  // Returns whether the average density error came below eta.
  bool solve_pressure(float dt, SolveStart start, StepReport& report) {
    if (dfsph()) return solve_density_dfsph(dt, report);
    const std::size_t n = liquid_.position.size();
    const PressureSolverSettings& ps = setup_.pressure;
    const float delta = pcisph_delta(pcisph_sum_, dt, particle_mass_, setup_.liquid.rest_density);
    const CorrectPressure correct{listed_density(Exec::ptr(predicted_)), delta, Exec::ptr(pressure_),
                                  Exec::ptr(density_error_)};
    const ComputePressureAcceleration pressure_acceleration{listed_particles(), Exec::ptr(pressure_), Exec::ptr(pressure_acc_)};
    if (start == SolveStart::Cold) {
      exec_.parallel_for(n, ClearPressure{Exec::ptr(pressure_), Exec::ptr(pressure_acc_)});
    } else {
      exec_.parallel_for(n, StartPressure{kWarmStartShare, Exec::ptr(pressure_start_), Exec::ptr(pressure_)});
      exec_.parallel_for(n, pressure_acceleration);
    }
    int iteration = 0;
    float error = 0;
    while (iteration < ps.max_iterations) {
      exec_.parallel_for(n, PredictPosition{Exec::ptr(liquid_.position), Exec::ptr(liquid_.velocity), Exec::ptr(nonpressure_acc_),
                                            Exec::ptr(pressure_acc_), dt, Exec::ptr(predicted_)});
      exec_.parallel_for(n, correct);
      exec_.parallel_for(n, pressure_acceleration);
      ++iteration;
      error = average_density_error();
      if (iteration >= ps.min_iterations && error <= ps.max_density_error) break;
    }
    report.pressure_iterations = iteration;
    report.density_error = error;
    return error <= ps.max_density_error;
  }

  // Sorting the particles themselves (not just an index) keeps neighbours
  // close in memory.
  void sort_liquid() {
    const std::size_t n = liquid_.position.size();
    liquid_grid_.sort(exec_, liquid_.position);
    const std::uint32_t* order = Exec::ptr(liquid_grid_.order);
    exec_.parallel_for(n, Gather<Vec3>{order, Exec::ptr(liquid_.position), Exec::ptr(position_tmp_)});
    exec_.parallel_for(n, Gather<Vec3>{order, Exec::ptr(liquid_.velocity), Exec::ptr(velocity_tmp_)});
    exec_.parallel_for(n, Gather<std::uint32_t>{order, Exec::ptr(liquid_.id), Exec::ptr(id_tmp_)});
    exec_.parallel_for(n, Gather<MassUnits>{order, Exec::ptr(liquid_.units), Exec::ptr(units_tmp_)});
    exec_.parallel_for(n, Gather<float>{order, Exec::ptr(liquid_.temperature), Exec::ptr(temperature_tmp_)});
    liquid_.position.swap(position_tmp_);
    liquid_.velocity.swap(velocity_tmp_);
    liquid_.id.swap(id_tmp_);
    liquid_.units.swap(units_tmp_);
    liquid_.temperature.swap(temperature_tmp_);
    if (setup_.pressure.warm_start) {  // the last step's pressures, for a warm solve
      exec_.parallel_for(n, Gather<float>{order, Exec::ptr(pressure_), Exec::ptr(temperature_tmp_)});
      pressure_.swap(temperature_tmp_);
    }
    liquid_grid_.find_ranges(exec_);
  }

  // Merging and redistribution (paper Sec. 6.3, Eq. 18), only while some
  // particle is lighter than the adaptivity threshold.
  // Returns whether it ran (and may have merged, removed or reordered particles).
  bool adapt_masses() {
    const std::size_t n = liquid_.size();
    const auto small = static_cast<MassUnits>(adaptivity_params_.small_weight * kFullParticleUnits);
    if (exec_.find_first(n, IsLighterThan{Exec::ptr(liquid_.units), small}) == n) return false;
    adaptivity_.adapt(exec_, liquid_, adaptivity_params_);
    if (liquid_.size() != n) resize_scratch(liquid_.size());
    return true;
  }

  // DomainLeaving::Remove: the particles the last step carried past the
  // domain's box leave the shot, their units into the ledger (computed once,
  // taken from the liquid and given to liquid_out). The step's own frame
  // showed them where they went; the air saw them on its boundary cells.
  bool remove_leaving_particles(StepReport& report) {
    if (setup_.leaving != DomainLeaving::Remove) return false;
    const std::size_t n = liquid_.size();
    const Vec3 lo = setup_.domain_min, hi = setup_.domain_max;
    const double leaving = exec_.sum(n, CountOutsideBox{Exec::ptr(liquid_.position), lo, hi});
    if (leaving == 0) return false;
    const double units = exec_.sum(n, UnitsOutsideBox{Exec::ptr(liquid_.position), Exec::ptr(liquid_.units), lo, hi});
    exec_.parallel_for(n, EmptyOutsideBox{Exec::ptr(liquid_.position), lo, hi, Exec::ptr(liquid_.units)});
    // Also drops any particle that evaporated completely, as adaptivity would.
    adaptivity_.remove_empty(exec_, liquid_);
    resize_scratch(liquid_.size());
    left_domain_units_ += static_cast<std::uint64_t>(units);
    left_domain_particles_ += static_cast<std::uint64_t>(leaving);
    report.particles_left_domain = static_cast<int>(leaving);
    return true;
  }

  void check_stability(Phase phase) {
    const std::size_t n = liquid_.position.size();
    float vmax = setup_.max_speed;
    // While settling there is no ledger to take leaving particles: they stop the run.
    const bool may_leave = setup_.leaving == DomainLeaving::Remove && phase == Phase::Running;
    std::size_t bad = exec_.find_first(n, IsUnstable{Exec::ptr(liquid_.position), Exec::ptr(liquid_.velocity), setup_.domain_min,
                                                     setup_.domain_max, vmax * vmax, may_leave});
    if (bad == n) return;
    Vec3 x = Exec::download(liquid_.position)[bad], v = Exec::download(liquid_.velocity)[bad];
    std::uint32_t id = Exec::download(liquid_.id)[bad];
    std::ostringstream detail;
    if (phase == Phase::Settling) detail << "while settling (settling step " << settling_steps_ << "): ";
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

  void check_air_stability() const {
    if (!air_) return;
    const NonFiniteValue bad = air_->first_non_finite(exec_);
    if (!bad.quantity) return;
    const MacGrid& g = air_->grid();
    std::ostringstream where;
    if (bad.axis < 0) {
      const int nx = g.nx, ny = g.ny;
      const int i = static_cast<int>(bad.index % nx), j = static_cast<int>(bad.index / nx % ny), k = static_cast<int>(bad.index / nx / ny);
      where << "air cell " << bad.index << " (i, j, k) = (" << i << ", " << j << ", " << k << ")";
    } else {
      where << "air face " << bad.index << " normal to " << "xyz"[bad.axis];
    }
    throw InstabilityError(steps_, bad.quantity, where.str());
  }

  Exec exec_;
  SimulationSetup setup_;
  CubicSplineKernel kernel_{};
  float particle_mass_ = 0;
  float pcisph_sum_ = 0;
  ParticleGrid<Exec> liquid_grid_, rigid_grid_;
  AdaptiveParticles<Exec> liquid_;  // the state carried from step to step
  MassAdaptivity<Exec> adaptivity_{UniformGrid{}};
  NeighborListBuffers<Exec> liquid_neighbors_, rigid_neighbors_;
  ListedPairs liquid_pairs_{}, rigid_pairs_{};  // of the liquid particles, with the pairs' gradient factors
  NeighborListBuffers<Exec> rigid_rigid_neighbors_;  // static, built once
  TransposedList liquid_near_rigid_;                  // CPU: rigid_pairs_ from the rigid side, for conduction
  ListedPairs rigid_rigid_pairs_{};
  AdaptivityParameters adaptivity_params_;
  Buffer<Vec3> position_tmp_, velocity_tmp_, predicted_, nonpressure_acc_, pressure_acc_;
  Buffer<std::uint32_t> id_tmp_;
  Buffer<MassUnits> units_tmp_;
  Buffer<float> temperature_tmp_, mass_, volume_, density_, pressure_, pressure_start_, density_error_;
  Buffer<float> dfsph_factor_, stiffness_, divergence_pressure_;  // DFSPH's alpha_i, kappa_i and its divergence solve's pressure
  Buffer<float> surface_area_, liquid_rate_;
  Buffer<Vec3> rigid_position_;
  Buffer<float> rigid_volume_, rigid_temperature_, rigid_rate_, rigid_adhesion_;
  Buffer<Vec3> normal_, tension_acc_;
  bool has_adhesion_ = false;
  Buffer<std::uint8_t> rigid_held_;
  float area_calibration_ = 1;
  float diffusion_dt_limit_ = 1e30f;  // explicit heat conduction and viscosity
  std::int64_t steps_ = 0;
  double time_ = 0;
  float last_max_acceleration_ = 0;
  ConvergedStepLimit converged_limit_;
  StepLimit step_limit_ = StepLimit::MaxStep;  // of the step next_time_step last planned
  std::int64_t settling_steps_ = 0;  // taken by settle; its last acceleration bounds the first step
  StepReport report_;
  SurfaceTextures<Exec> surfaces_;
  std::optional<AirGrid<Exec>> air_;
  AirCoupling<Exec> coupling_;
  ParticlePathForce<Exec> path_force_;
  WaterLedger initial_water_;
  Buffer<std::uint8_t> emitted_;
  Buffer<float> seed_temperature_;
  std::uint32_t next_id_ = 0;           // for emitted particles
  std::uint64_t emitted_particles_ = 0;
  std::uint64_t left_domain_particles_ = 0, left_domain_units_ = 0;  // DomainLeaving::Remove
};

}  // namespace dp
