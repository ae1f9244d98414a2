#pragma once
// The air phase (paper Sec. 4.2, Alg. 1 lines 7-11) on either backend: a
// staggered grid with velocity, temperature and vapor density, its liquid and
// rigid particles as boundaries. One step:
//   line 7   classify(): air, solid (rigid), liquid, inflow cells
//   line 8   inflow values, boundary conditions, buoyancy (Eq. 5) and
//            vorticity confinement
//   line 9   advection: vapor conservatively, temperature and velocity
//            semi-Lagrangian (optionally MacCormack)
//   line 10  diffusion of heat and vapor
//   line 11  pressure projection, multigrid-preconditioned CG
// Vapor is stored in double: the flux-form transport conserves it to
// rounding, and float rounding (1e-7 per cell update) would add up to more
// than the 1e-9 drift the mass ledger is held to over thousands of steps;
// double's 1e-16 keeps it far below. Velocity and temperature are float;
// temperature is kept as its excess over the ambient T_amb, which is what
// buoyancy (Eq. 5) reads and which float then holds to 1e-7 of the excess
// rather than to 1e-7 of 293 K (3e-5 K, enough to break a symmetric flow's
// symmetry within a few dozen steps).
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "air/air_settings.h"
#include "air/air_state.h"
#include "simulation_state.h"
#include "air/boundary_conditions.h"
#include "air/buoyancy_fedkiw2001.h"
#include "air/classify_cells.h"
#include "air/conjugate_gradient.h"
#include "air/diffusion_explicit.h"
#include "air/maccormack_selle2008.h"
#include "air/padded_field.h"
#include "air/pressure_projection.h"
#include "air/semi_lagrangian_stam1999.h"
#include "air/vapor_transport_fv.h"
#include "air/vorticity_confinement_fedkiw2001.h"
#include "backend/sorted_runs.h"

namespace dp {

// f(std::integral_constant<int, A>{}) for the axes A = 0, 1, 2: the face
// kernels take their axis as a template argument, which folds their index
// arithmetic and axis selects (the vapor fluxes took a third less time).
template <class F>
void for_each_axis(const F& f) {
  f(std::integral_constant<int, 0>{});
  f(std::integral_constant<int, 1>{});
  f(std::integral_constant<int, 2>{});
}

struct FillValue {
  template <class T>
  struct Into {
    T value;
    T* out;
    DP_HD void operator()(std::size_t i) const { out[i] = value; }
  };
};

template <class T>
struct ValueAsDouble {
  const T* v;
  DP_HD double operator()(std::size_t i) const { return static_cast<double>(v[i]); }
};

template <class T>
struct IsNotFinite {
  const T* v;
  DP_HD bool operator()(std::size_t i) const { return !isfinite(v[i]); }
};

// Where a field of the grid first holds NaN or infinity.
struct NonFiniteValue {
  const char* quantity = nullptr;  // null: every value is finite
  int axis = -1;                   // the face axis for velocities, -1 for cell fields
  std::size_t index = 0;           // cell or face index
};

// Vapor (kg) and temperature change (K) per cell from the coupling, added
// where the cell carries air; each cell reads only its own entry.
struct AddCellSources {
  const double* vapor_mass;
  const float* temperature_change;
  double cell_volume;
  double* vapor;
  float* temperature;
  DP_HD void operator()(std::size_t c) const {
    if (vapor_mass) vapor[c] += vapor_mass[c] / cell_volume;
    if (temperature_change) temperature[c] += temperature_change[c];
  }
};

// What the coupling (paper Sec. 5-6) reads: device pointers to the cells.
struct AirCellsView {
  MacGrid grid;
  const std::uint8_t* kind;
  const double* vapor;               // kg/m^3
  const float* temperature_excess;   // T - T_amb, K
  float ambient_temperature;         // K
  const float* u;
  const float* v;
  const float* w;
  DP_HD Vec3 velocity_at(Vec3 p) const { return face_velocity(grid, u, v, w).at(grid_point_of(grid, p)); }
  DP_HD double vapor_at(Vec3 p) const { return cell_lattice(grid, vapor).sample(grid_point_of(grid, p)); }
  DP_HD float temperature_at(Vec3 p) const {
    return ambient_temperature + cell_lattice(grid, temperature_excess).sample(grid_point_of(grid, p));
  }
};

// Seconds between laps, each lap waiting for the backend first; nothing
// when off.
template <class Exec>
class PartTimer {
 public:
  PartTimer(const Exec& exec, bool on) : exec_(exec), on_(on) {
    if (on_) exec_.synchronize();  // work queued before the step is not the first part's
    last_ = std::chrono::steady_clock::now();
  }
  void lap(double& seconds) {
    if (!on_) return;
    exec_.synchronize();
    const auto now = std::chrono::steady_clock::now();
    seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  const Exec& exec_;
  bool on_;
  std::chrono::steady_clock::time_point last_;
};

template <class Exec>
class AirGrid {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  // Largest outflow Courant number of a cell in one vapor transport
  // sub-step (positive below 2/3, see CellOutflowSpeed) and diffusion number
  // of one diffusion sub-step.
  static constexpr double kMaxVaporCourant = 0.6;
  static constexpr double kMaxDiffusionNumber = 0.9;

  // `rigid`: the static rigid particles in their neighbour grid (a view with
  // no particles when there are none).
  AirGrid(const Exec& exec, const AirSettings& settings, Vec3 gravity, const GridView& rigid)
      : settings_(settings), grid_(mac_grid_covering(settings.domain_min, settings.domain_max, settings.resolution)) {
    for (int f = 0; f < 6; ++f)
      if (settings.open_face[f]) faces_.open_mask |= 1u << f;
    const float g = length(gravity);
    buoyancy_ = BuoyancyParameters{g > 0 ? (-1.0f / g) * gravity : Vec3{0, 1, 0}, settings.buoyancy_alpha,
                                   settings.buoyancy_beta};
    const std::size_t n = grid_.cell_count();
    for (auto* b : {&kind_, &static_kind_, &inflow_of_, &unknown_}) b->resize(n);
    for (auto* b : {&temperature_excess_, &temperature_tmp_, &temperature_back_, &phi_, &rhs_}) b->resize(n);
    const std::size_t slab = static_cast<std::size_t>(grid_.nx) * grid_.ny;
    omega_norm_.resize(n, slab);
    cell_velocity_.resize(n, slab);
    vapor_.resize(n);
    vapor_tmp_.resize(n);
    for (auto* b : {&omega_, &force_}) b->resize(n);
    for (int a = 0; a < 3; ++a) {
      u_[a].resize(grid_.face_count(a));
      u_tmp_[a].resize(grid_.face_count(a));
      u_back_[a].resize(grid_.face_count(a));
      vapor_flux_[a].resize(grid_.face_count(a));
      face_prescribed_[a].resize(grid_.face_count(a));
      face_value_[a].resize(grid_.face_count(a));
      exec.parallel_for(u_[a].size(), FillValue::Into<float>{0.0f, Exec::ptr(u_[a])});
    }
    Exec::upload(inflows_, settings.inflows);
    for (int a = 0; a < 3; ++a) Exec::upload(inflow_velocity_[a], inflow_velocities_along(settings.inflows, a));
    exec.parallel_for(n, FillValue::Into<double>{settings.ambient_vapor, Exec::ptr(vapor_)});
    exec.parallel_for(n, FillValue::Into<float>{0.0f, Exec::ptr(temperature_excess_)});
    exec.parallel_for(n, FillValue::Into<float>{0.0f, Exec::ptr(phi_)});
    exec.parallel_for(n, StaticCellKinds{grid_, rigid, Exec::ptr(static_kind_), Exec::ptr(inflow_of_), Exec::ptr(inflows_),
                                         static_cast<int>(settings.inflows.size())});
    kind_ = static_kind_;
    Exec::upload(inflow_cells_, inflow_cells_of(Exec::download(inflow_of_)));
    pcg_.resize(grid_.nx, grid_.ny, grid_.nz, faces_);
    if (settings.cycle_layout) pcg_.preconditioner().set_layout(*settings.cycle_layout);
    ledger_.initial = vapor_mass(exec);
  }

  const MacGrid& grid() const { return grid_; }
  const AirSettings& settings() const { return settings_; }
  const AirLedger& ledger() const { return ledger_; }
  CellKinds cells() const { return CellKinds{grid_, Exec::ptr(kind_), faces_}; }
  AirCellsView view() const {
    return AirCellsView{grid_, Exec::ptr(kind_), Exec::ptr(vapor_), Exec::ptr(temperature_excess_), settings_.ambient_temperature,
                        Exec::ptr(u_[0]), Exec::ptr(u_[1]), Exec::ptr(u_[2])};
  }

  // Alg. 1 line 7, from the liquid particles.
  void classify(const Exec& exec, ParticlePositions liquid) {
    exec.parallel_for(grid_.cell_count(), CopyBytes{Exec::ptr(static_kind_), Exec::ptr(kind_)});
    if (liquid.count > 0) exec.parallel_for(liquid.count, MarkLiquidCells{grid_, liquid, Exec::ptr(static_kind_), Exec::ptr(kind_)});
  }

  // Alg. 1 lines 8-11.
  AirStepReport step(const Exec& exec, float dt) {
    AirStepReport report;
    PartTimer timer{exec, settings_.time_parts};
    apply_inflows(exec);
    enforce_boundaries(exec);
    mark_unknowns(exec);
    timer.lap(report.seconds.inflows);
    // Scalars move with the last projected, divergence-free velocity, which
    // neither piles vapor up nor thins it out.
    report.advection_substeps = transport_vapor(exec, dt);
    timer.lap(report.seconds.vapor);
    advect_temperature(exec, dt);
    timer.lap(report.seconds.temperature);
    add_forces(exec, dt);
    timer.lap(report.seconds.forces);
    advect_velocity(exec, dt);
    timer.lap(report.seconds.velocity);
    report.diffusion_substeps = diffuse(exec, dt);
    timer.lap(report.seconds.diffusion);
    // advect_velocity left the prescribed faces enforced, and diffusion
    // moves no velocity.
    const PcgResult p = project_enforced(exec);
    timer.lap(report.seconds.projection);
    report.projection_iterations = p.iterations;
    report.projection_residual = p.relative_residual;
    return report;
  }

  // Inflow cells take their prescribed temperature and vapor; the vapor
  // this adds (or removes) goes to the ledger.
  void apply_inflows(const Exec& exec) {
    const std::size_t n = inflow_cells_.size();
    if (n == 0) return;
    const std::uint32_t* cells = Exec::ptr(inflow_cells_);
    ledger_.inflow_gain += exec.sum(n, at_keys(cells, InflowVaporGain{Exec::ptr(inflow_of_), Exec::ptr(inflows_), Exec::ptr(vapor_),
                                                                      static_cast<double>(grid_.cell_volume())}));
    exec.parallel_for(n, at_keys(cells, ApplyInflowScalars{Exec::ptr(inflow_of_), Exec::ptr(inflows_), settings_.ambient_temperature,
                                                           Exec::ptr(vapor_), Exec::ptr(temperature_excess_)}));
  }

  // Every face that is not free takes its prescribed velocity; which faces
  // those are is recorded for reapply_boundaries.
  void enforce_boundaries(const Exec& exec) {
    for_each_axis([&](auto axis) {
      constexpr int a = decltype(axis)::value;
      exec.parallel_for_3d(grid_.face_n(a, 0), grid_.face_n(a, 1), grid_.face_n(a, 2),
                           EnforceFaceVelocity<a>{cells(), Exec::ptr(inflow_of_), Exec::ptr(inflow_velocity_[a]), Exec::ptr(u_[a]),
                                                  Exec::ptr(face_prescribed_[a]), Exec::ptr(face_value_[a])});
    });
  }

  // enforce_boundaries again within a step, whose cells do not change.
  void reapply_boundaries(const Exec& exec) {
    for (int a = 0; a < 3; ++a)
      exec.parallel_for(u_[a].size(), ReapplyPrescribedFaces{Exec::ptr(face_prescribed_[a]), Exec::ptr(face_value_[a]),
                                                             Exec::ptr(u_[a])});
  }

  // Conservative vapor transport, sub-stepped so that no cell's outflow
  // Courant number exceeds kMaxVaporCourant; returns the number of sub-steps.
  int transport_vapor(const Exec& exec, float dt) {
    const double speed =
        exec.max_3d(grid_.nx, grid_.ny, grid_.nz, CellOutflowSpeed{grid_, Exec::ptr(u_[0]), Exec::ptr(u_[1]), Exec::ptr(u_[2])}, 0.0f);
    const double courant = speed * dt / grid_.dx;
    const int substeps = courant > kMaxVaporCourant ? static_cast<int>(std::ceil(courant / kMaxVaporCourant)) : 1;
    const float h = dt / static_cast<float>(substeps);
    for (int s = 0; s < substeps; ++s) {
      const VaporFaceFlux flux{cells(), Exec::ptr(vapor_), settings_.ambient_vapor, h};
      for_each_axis([&](auto axis) {
        constexpr int a = decltype(axis)::value;
        exec.parallel_for_3d(grid_.face_n(a, 0), grid_.face_n(a, 1), grid_.face_n(a, 2),
                             ComputeVaporFlux<a>{flux, Exec::ptr(u_[a]), Exec::ptr(vapor_flux_[a])});
      });
      const double* fx = Exec::ptr(vapor_flux_[0]);
      const double* fy = Exec::ptr(vapor_flux_[1]);
      const double* fz = Exec::ptr(vapor_flux_[2]);
      if (faces_.any_open()) {
        const std::size_t boundary = boundary_face_count(grid_);
        ledger_.open_in += exec.sum(boundary, OpenFaceVaporMass{grid_, fx, fy, fz, true});
        ledger_.open_out += exec.sum(boundary, OpenFaceVaporMass{grid_, fx, fy, fz, false});
      }
      exec.parallel_for_3d(grid_.nx, grid_.ny, grid_.nz, TransportVapor{grid_, Exec::ptr(vapor_), fx, fy, fz, Exec::ptr(vapor_tmp_)});
      vapor_.swap(vapor_tmp_);
    }
    return substeps;
  }

  void advect_temperature(const Exec& exec, float dt) {
    const FaceVelocity vel = face_velocity(grid_, Exec::ptr(u_[0]), Exec::ptr(u_[1]), Exec::ptr(u_[2]));
    advect_field<kCellCentres>(exec, cell_lattice(grid_, Exec::ptr(temperature_excess_)), vel, dt, temperature_tmp_,
                               temperature_back_);
    temperature_excess_.swap(temperature_tmp_);
  }

  // Explicit diffusion of heat and vapor; returns the sub-steps taken.
  int diffuse(const Exec& exec, float dt) {
    const double dx2 = static_cast<double>(grid_.dx) * grid_.dx;
    const double d_max = std::fmax(settings_.vapor_diffusivity, settings_.heat_diffusivity);
    // A cell's weights on its neighbours sum to 6 rate, or up to 9 rate in a
    // corner of open faces (2 rate each); below 1 the update is a convex
    // combination and cannot overshoot.
    const double number = (faces_.any_open() ? 9.0 : 6.0) * d_max * dt / dx2;
    if (!(d_max > 0)) return 0;
    const int substeps = number > kMaxDiffusionNumber ? static_cast<int>(std::ceil(number / kMaxDiffusionNumber)) : 1;
    const double h = static_cast<double>(dt) / substeps;
    for (int s = 0; s < substeps; ++s) {
      if (settings_.vapor_diffusivity > 0) {
        const double rate = settings_.vapor_diffusivity * h / dx2;
        if (faces_.any_open()) {
          const std::size_t boundary = boundary_face_count(grid_);
          ledger_.open_in += exec.sum(boundary, OpenFaceDiffusion{cells(), Exec::ptr(vapor_), rate, settings_.ambient_vapor, true});
          ledger_.open_out += exec.sum(boundary, OpenFaceDiffusion{cells(), Exec::ptr(vapor_), rate, settings_.ambient_vapor, false});
        }
        exec.parallel_for_3d(grid_.nx, grid_.ny, grid_.nz,
                             DiffuseExplicit<double>{cells(), Exec::ptr(vapor_), rate, settings_.ambient_vapor, Exec::ptr(vapor_tmp_)});
        vapor_.swap(vapor_tmp_);
      }
      if (settings_.heat_diffusivity > 0) {
        // The temperature is kept as its excess over the ambient, 0 outside.
        exec.parallel_for_3d(grid_.nx, grid_.ny, grid_.nz, DiffuseExplicit<float>{cells(), Exec::ptr(temperature_excess_), settings_.heat_diffusivity * h / dx2, 0.0f,
                                                    Exec::ptr(temperature_tmp_)});
        temperature_excess_.swap(temperature_tmp_);
      }
    }
    return substeps;
  }

  // Makes the velocity divergence-free in the air cells. The last step's
  // phi is the first guess: the pressure changes little between steps.
  PcgResult project(const Exec& exec) {
    enforce_boundaries(exec);
    mark_unknowns(exec);
    return project_enforced(exec);
  }

  // Coupling (paper Sec. 5-6): per-cell vapor mass (kg) and temperature
  // change (K), either may be null; the vapor goes to the ledger.
  void add_cell_sources(const Exec& exec, const double* vapor_mass, const float* temperature_change) {
    const std::size_t n = grid_.cell_count();
    if (vapor_mass) ledger_.exchanged += exec.sum(n, ValueAsDouble<double>{vapor_mass});
    exec.parallel_for(n, AddCellSources{vapor_mass, temperature_change, static_cast<double>(grid_.cell_volume()),
                                        Exec::ptr(vapor_), Exec::ptr(temperature_excess_)});
  }

  // The same for a vapor mass that is 0 outside the `count` cells listed
  // (the coupling's active cells): only those are updated, while the
  // ledger still sums the whole grid, whose one blocked order keeps the
  // sum's bits independent of which cells are listed.
  void add_vapor_at(const Exec& exec, const std::uint32_t* cells, std::size_t count, const double* vapor_mass) {
    ledger_.exchanged += exec.sum(grid_.cell_count(), ValueAsDouble<double>{vapor_mass});
    if (count == 0) return;
    exec.parallel_for(count, at_keys(cells, AddCellSources{vapor_mass, nullptr, static_cast<double>(grid_.cell_volume()),
                                                           Exec::ptr(vapor_), Exec::ptr(temperature_excess_)}));
  }

  double vapor_mass(const Exec& exec) const {
    return exec.sum(grid_.cell_count(), ValueAsDouble<double>{Exec::ptr(vapor_)}) * grid_.cell_volume();
  }

  AirSnapshot snapshot() const {
    AirSnapshot s;
    s.grid = grid_;
    s.kind = Exec::download(kind_);
    s.vapor = Exec::download(vapor_);
    s.temperature = Exec::download(temperature_excess_);
    for (float& t : s.temperature) t += settings_.ambient_temperature;
    s.u = Exec::download(u_[0]);
    s.v = Exec::download(u_[1]);
    s.w = Exec::download(u_[2]);
    s.ledger = ledger_;
    return s;
  }

  NonFiniteValue first_non_finite(const Exec& exec) const {
    const std::size_t n = grid_.cell_count();
    std::size_t at = exec.find_first(n, IsNotFinite<double>{Exec::ptr(vapor_)});
    if (at < n) return NonFiniteValue{"air vapor density", -1, at};
    at = exec.find_first(n, IsNotFinite<float>{Exec::ptr(temperature_excess_)});
    if (at < n) return NonFiniteValue{"air temperature", -1, at};
    for (int a = 0; a < 3; ++a) {
      at = exec.find_first(u_[a].size(), IsNotFinite<float>{Exec::ptr(u_[a])});
      if (at < u_[a].size()) return NonFiniteValue{"air velocity", a, at};
    }
    return NonFiniteValue{};
  }

  // What carries over to the next step, bit for bit (simulation_state.h).
  AirGridState state() const {
    AirGridState s;
    s.u = Exec::download(u_[0]);
    s.v = Exec::download(u_[1]);
    s.w = Exec::download(u_[2]);
    s.temperature_excess = Exec::download(temperature_excess_);
    s.vapor = Exec::download(vapor_);
    s.pressure = Exec::download(phi_);
    s.kind = Exec::download(kind_);
    s.ledger = ledger_;
    return s;
  }
  // Throws std::invalid_argument when the sizes are not this grid's.
  void restore(const AirGridState& s) {
    const std::size_t n = grid_.cell_count();
    const bool fits = s.u.size() == u_[0].size() && s.v.size() == u_[1].size() && s.w.size() == u_[2].size() &&
                      s.temperature_excess.size() == n && s.vapor.size() == n && s.pressure.size() == n && s.kind.size() == n;
    if (!fits) throw std::invalid_argument("air state: field sizes differ from the grid's");
    Exec::upload(u_[0], s.u);
    Exec::upload(u_[1], s.v);
    Exec::upload(u_[2], s.w);
    Exec::upload(temperature_excess_, s.temperature_excess);
    Exec::upload(vapor_, s.vapor);
    Exec::upload(phi_, s.pressure);
    Exec::upload(kind_, s.kind);
    ledger_ = s.ledger;
  }

  // For tests and restarts: replace the fields (sizes as in snapshot()).
  // Setting vapor restarts the ledger from the new mass.
  void set_velocity(const std::vector<float>& u, const std::vector<float>& v, const std::vector<float>& w) {
    Exec::upload(u_[0], u);
    Exec::upload(u_[1], v);
    Exec::upload(u_[2], w);
  }
  void set_temperature(const std::vector<float>& t) {
    std::vector<float> excess(t);
    for (float& e : excess) e -= settings_.ambient_temperature;
    Exec::upload(temperature_excess_, excess);
  }
  void set_vapor(const Exec& exec, const std::vector<double>& rho) {
    Exec::upload(vapor_, rho);
    ledger_ = AirLedger{};
    ledger_.initial = vapor_mass(exec);
  }

 private:
  // Buoyancy (Eq. 5) and vorticity confinement, explicit over dt. Within
  // step() only, as advect_velocity: both reapply the face verdicts that
  // enforce_boundaries recorded at the step's start.
  void add_forces(const Exec& exec, float dt) {
    for_each_axis([&](auto axis) {
      constexpr int a = decltype(axis)::value;
      if (buoyancy_.up[a] == 0.0f) return;  // no pass over faces the kernel leaves alone
      exec.parallel_for_3d(grid_.face_n(a, 0), grid_.face_n(a, 1), grid_.face_n(a, 2),
                           AddBuoyancy<a>{grid_, buoyancy_, Exec::ptr(vapor_), Exec::ptr(temperature_excess_), dt, Exec::ptr(u_[a])});
    });
    if (settings_.vorticity_epsilon > 0) {
      // The finest pressure level's stencil marks each cell's air neighbours
      // (mark_unknowns ran at the start of the step).
      const PoissonLevel air = pcg_.preconditioner().view(0);
      const DifferenceScales scales = difference_scales(grid_.dx);
      const std::size_t n = grid_.cell_count();
      exec.parallel_for_3d(grid_.nx, grid_.ny, grid_.nz, CellCentredVelocity{grid_, Exec::ptr(u_[0]), Exec::ptr(u_[1]), Exec::ptr(u_[2]),
                                                                             cell_velocity_.ptr()});
      exec.parallel_for(n, ComputeVorticity{air, scales, cell_velocity_.ptr(), Exec::ptr(omega_), omega_norm_.ptr()});
      exec.parallel_for(n, ComputeConfinementForce{air, scales, grid_.dx, Exec::ptr(omega_), omega_norm_.ptr(),
                                                   settings_.vorticity_epsilon, Exec::ptr(force_)});
      for_each_axis([&](auto axis) {
        constexpr int a = decltype(axis)::value;
        exec.parallel_for_3d(grid_.face_n(a, 0), grid_.face_n(a, 1), grid_.face_n(a, 2),
                             AddCellForceToFaces<a>{grid_, Exec::ptr(force_), dt, Exec::ptr(u_[a])});
      });
    }
    reapply_boundaries(exec);
  }

  // Every component is advected by the velocity at the start of the call.
  void advect_velocity(const Exec& exec, float dt) {
    const FaceVelocity vel = face_velocity(grid_, Exec::ptr(u_[0]), Exec::ptr(u_[1]), Exec::ptr(u_[2]));
    advect_field<0>(exec, vel.u, vel, dt, u_tmp_[0], u_back_[0]);
    advect_field<1>(exec, vel.v, vel, dt, u_tmp_[1], u_back_[1]);
    advect_field<2>(exec, vel.w, vel, dt, u_tmp_[2], u_back_[2]);
    for (int a = 0; a < 3; ++a) u_[a].swap(u_tmp_[a]);
    reapply_boundaries(exec);
  }

  // The pressure's unknowns, the air cells, and the stencils over them,
  // from the cells' kinds: once per step, as the kinds change only when the
  // cells are classified.
  void mark_unknowns(const Exec& exec) {
    exec.parallel_for(grid_.cell_count(), MarkAirUnknowns{Exec::ptr(kind_), Exec::ptr(unknown_)});
    pcg_.set_unknowns(exec, unknown_);
  }

  // project() where every prescribed face already holds its value and the
  // unknowns are marked.
  PcgResult project_enforced(const Exec& exec) {
    exec.parallel_for_3d(grid_.nx, grid_.ny, grid_.nz, ComputeProjectionRhs{cells(), Exec::ptr(u_[0]), Exec::ptr(u_[1]), Exec::ptr(u_[2]), Exec::ptr(rhs_)});
    const PcgResult result = pcg_.solve(exec, rhs_, phi_, settings_.projection_tolerance, settings_.projection_max_iterations);
    for_each_axis([&](auto axis) {
      constexpr int a = decltype(axis)::value;
      exec.parallel_for_3d(grid_.face_n(a, 0), grid_.face_n(a, 1), grid_.face_n(a, 2),
                           SubtractPressureGradient<a>{cells(), Exec::ptr(phi_), Exec::ptr(u_[a])});
    });
    return result;
  }

  // Semi-Lagrangian, or MacCormack on top of it, from `source` into `out`;
  // `Points` names source's lattice (mac_shift).
  template <int Points, class T>
  void advect_field(const Exec& exec, const Lattice<T>& source, const FaceVelocity& vel, float dt, Buffer<T>& out,
                    Buffer<T>& scratch) {
    const float c = dt / grid_.dx;
    const int nx = source.nx, ny = source.ny, nz = source.nz;
    exec.parallel_for_3d(nx, ny, nz, AdvectSemiLagrangian<T, Points>{source, vel, c, Exec::ptr(out)});
    if (settings_.advection == AirAdvection::SemiLagrangian) return;
    // Forward step in `out`, backward step in `scratch`; the corrected value
    // overwrites the backward one in place (each point reads only its own).
    Lattice<T> forward = source;
    forward.value = Exec::ptr(out);
    exec.parallel_for_3d(nx, ny, nz, AdvectSemiLagrangian<T, Points>{forward, vel, -c, Exec::ptr(scratch)});
    exec.parallel_for_3d(nx, ny, nz, MacCormackCorrect<T, Points>{source, vel, c, Exec::ptr(out), Exec::ptr(scratch), Exec::ptr(scratch)});
    out.swap(scratch);
  }

  AirSettings settings_;
  MacGrid grid_;
  DomainFaces faces_;
  BuoyancyParameters buoyancy_{};
  Buffer<AirInflow> inflows_;
  Buffer<float> inflow_velocity_[3];  // per axis, by inflow_of_ (inflow_velocities_along)
  Buffer<std::uint8_t> kind_, static_kind_, inflow_of_, unknown_;
  Buffer<std::uint32_t> inflow_cells_;  // the cells inflow_of_ names, in order (inflow_cells_of)
  Buffer<float> u_[3], u_tmp_[3], u_back_[3];
  // Per face, from the last enforce_boundaries: 1 where prescribed, and the value.
  Buffer<std::uint8_t> face_prescribed_[3];
  Buffer<float> face_value_[3];
  Buffer<float> temperature_excess_, temperature_tmp_, temperature_back_, phi_, rhs_;
  PaddedField<Exec, float> omega_norm_;  // read by the vorticity stencil
  PaddedField<Exec, Vec3> cell_velocity_;
  Buffer<double> vapor_, vapor_tmp_, vapor_flux_[3];
  Buffer<Vec3> omega_, force_;
  PoissonPcg<Exec> pcg_;
  AirLedger ledger_;
};

}  // namespace dp
