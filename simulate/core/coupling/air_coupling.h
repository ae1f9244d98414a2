#pragma once
// Phase 3 of Algorithm 1 (paper Sec. 4.4, 5, 6) on a backend, the air's
// side of it: neighbourhoods between particles, texels and cells (line 12),
// heat between particles and cells (line 13, Eq. 13-15), particle
// evaporation (line 15) and texels <-> cells (line 16, Alg. 2). Every
// transfer is computed once per particle-cell or texel-cell pair and
// gathered by both sides; water moves in whole texel mass units, counted
// exactly here for the water ledger.
#include <cstdint>
#include <vector>

#include "air/air_grid.h"
#include "air/vorticity_confinement_fedkiw2001.h"
#include "coupling/cell_stencil.h"
#include "coupling/coupling_settings.h"
#include "coupling/heat_grid_particles.h"
#include "coupling/particle_evaporation.h"
#include "coupling/texel_vapor_exchange.h"
#include "surface/surface_textures.h"

namespace dp {

template <class Exec>
class AirCoupling {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  __extension__ typedef __int128 Units;  // running totals: beyond 64 bits after 128 particles' mass

  // Static neighbourhoods: rigid particles and texels <-> cells (rigids do
  // not move, Sec. 4.4).
  void prepare(const Exec& exec, const CouplingSettings& settings, const AirGrid<Exec>& air, const Buffer<Vec3>& rigid_position,
               SurfaceTextures<Exec>& surfaces) {
    settings_ = settings;
    const MacGrid& g = air.grid();
    rigid_.build(exec, g, rigid_position);
    rigid_run_of_cell_.assign(g.cell_count(), kNoRun);
    if (rigid_.cells.active_cells() > 0)
      exec.parallel_for(rigid_.cells.active_cells(), MarkRunOfCell{rigid_.cells.cell(), Exec::ptr(rigid_run_of_cell_)});
    texels_.resize(surfaces.count());
    for (std::size_t i = 0; i < surfaces.count(); ++i) texels_[i].prepare(exec, g, surfaces.texture(i).position, surfaces.texture(i).normal);
    // Whole-grid arrays for AirGrid, written only at active cells (the
    // liquid's are cleared where the last step wrote them).
    temperature_change_.assign(g.cell_count(), 0.0f);
    cell_velocity_.resize(g.cell_count());
    vapor_kg_.assign(g.cell_count(), 0.0);
    heat_written_.resize(0);
    vapor_written_.resize(0);
  }

  // Alg. 1 line 12: liquid particles <-> cells, every step.
  void find_neighbours(const Exec& exec, const AirGrid<Exec>& air, const Buffer<Vec3>& liquid_position) {
    liquid_.build(exec, air.grid(), liquid_position);
    velocity_fresh_ = false;
  }

  // Alg. 1 line 13 (Eq. 13-15): both particle sets' pairs from the
  // temperatures at the start, then the cells gather them.
  void exchange_heat(const Exec& exec, AirGrid<Exec>& air, const HeatSurfels& liquid, const HeatSurfels& rigid, float dt,
                     std::uint64_t step) {
    if (!settings_.heat_exchange) return;
    const AirCellsView view = air.view();
    const AirHeatProperties& a = settings_.air;
    if (liquid_.size > 0)
      exec.parallel_for(liquid_.size, ExchangeParticleCellHeat{liquid, view, a, Exec::ptr(liquid_.pair_cell), Exec::ptr(liquid_.pair_alpha),
                                                               dt, step, Exec::ptr(liquid_.pair_heat)});
    if (rigid_.size > 0)
      exec.parallel_for(rigid_.size, ExchangeParticleCellHeat{rigid, view, a, Exec::ptr(rigid_.pair_cell), Exec::ptr(rigid_.pair_alpha),
                                                              dt, step, Exec::ptr(rigid_.pair_heat)});
    const MacGrid& g = air.grid();
    const double capacity = static_cast<double>(a.density) * a.specific_heat * g.cell_volume();
    float* change = Exec::ptr(temperature_change_);
    if (heat_written_.size() > 0) exec.parallel_for(heat_written_.size(), FillCells<float>{Exec::ptr(heat_written_), 0.0f, change});
    const CellPairs none{nullptr, nullptr, nullptr};
    if (rigid_.size > 0)
      exec.parallel_for(rigid_.cells.active_cells(), GatherCellHeat{rigid_.cells.cell(), rigid_.cell_pairs(), none, nullptr, capacity, change});
    if (liquid_.size > 0)
      exec.parallel_for(liquid_.cells.active_cells(), GatherCellHeat{liquid_.cells.cell(), liquid_.cell_pairs(), rigid_.cell_pairs(),
                                                                     Exec::ptr(rigid_run_of_cell_), capacity, change});
    heat_written_ = liquid_.cells.runs.key;
    air.add_cell_sources(exec, nullptr, change);
  }

  // Alg. 1 line 15: particles -> cells; `units` lose what the air gains.
  void evaporate_particles(const Exec& exec, AirGrid<Exec>& air, const Buffer<float>& area, Buffer<float>& temperature,
                           const Buffer<std::uint32_t>& id, Buffer<MassUnits>& units, float specific_heat, double kg_per_unit,
                           float dt, std::uint64_t step) {
    if (!settings_.particle_evaporation || liquid_.size == 0) return;
    find_cell_velocity(exec, air);
    exec.parallel_for(liquid_.size, EvaporateParticles{air.view(), Exec::ptr(cell_velocity_), Exec::ptr(liquid_.pair_cell),
                                                       Exec::ptr(liquid_.pair_alpha), Exec::ptr(area), Exec::ptr(temperature),
                                                       Exec::ptr(id), settings_.rate_coefficients(), dt, kg_per_unit, step,
                                                       Exec::ptr(units), Exec::ptr(liquid_.pair_eva),
                                                       settings_.latent_heat ? settings_.latent_heat_j_kg / specific_heat : 0.0f});
    if (vapor_written_.size() > 0)
      exec.parallel_for(vapor_written_.size(), FillCells<double>{Exec::ptr(vapor_written_), 0.0, Exec::ptr(vapor_kg_)});
    const std::size_t active = liquid_.cells.active_cells();
    net_units_.resize(active);
    exec.parallel_for(active, UpdateCellVapor{liquid_.cells.cell(), liquid_.cells.begin(), Exec::ptr(liquid_.cells.sorted_pair),
                                              Exec::ptr(liquid_.pair_eva), kg_per_unit, Exec::ptr(net_units_), Exec::ptr(vapor_kg_)});
    vapor_written_ = liquid_.cells.runs.key;
    air.add_vapor_at(exec, liquid_.cells.cell(), active, Exec::ptr(vapor_kg_));
    liquid_to_air_ += exact_units_sum(exec, active, Exec::ptr(net_units_));
  }

  // Alg. 1 line 16: Alg. 2 for each textured rigid in turn.
  void exchange_texels(const Exec& exec, AirGrid<Exec>& air, SurfaceTextures<Exec>& surfaces, float dt) {
    if (!settings_.texel_exchange) return;
    ExchangeParameters p;
    p.coefficients = settings_.rate_coefficients();
    p.dt = dt;
    p.kg_per_unit = surfaces.kg_per_unit();
    p.wet_threshold = settings_.wet_threshold;
    if (!texels_.empty()) find_cell_velocity(exec, air);
    for (std::size_t i = 0; i < texels_.size(); ++i) {
      auto& t = surfaces.texture(i);
      const TexelExchangeView view{Exec::ptr(t.position), Exec::ptr(t.area), Exec::ptr(t.temperature), Exec::ptr(t.wetting),
                                   Exec::ptr(t.max_mass), Exec::ptr(t.mass)};
      texels_to_air_ += texels_[i].exchange(exec, view, air, Exec::ptr(cell_velocity_), p);
    }
    velocity_fresh_ = false;  // the next step's air moves
  }

  Units liquid_to_air_units() const { return liquid_to_air_; }
  Units texels_to_air_units() const { return texels_to_air_; }
  // For restarts: the exact totals so far.
  void restore_units(Units liquid_to_air, Units texels_to_air) {
    liquid_to_air_ = liquid_to_air;
    texels_to_air_ = texels_to_air;
  }

 private:
  // Once a step, and only at the cells a stencil reads: the liquid's and
  // the texels' active cells.
  void find_cell_velocity(const Exec& exec, const AirGrid<Exec>& air) {
    if (velocity_fresh_) return;
    const AirCellsView v = air.view();
    const CellCentredVelocity at{air.grid(), v.u, v.v, v.w, Exec::ptr(cell_velocity_)};
    if (liquid_.cells.active_cells() > 0) exec.parallel_for(liquid_.cells.active_cells(), at_keys(liquid_.cells.cell(), at));
    for (const auto& t : texels_)
      if (t.active_cell_count() > 0) exec.parallel_for(t.active_cell_count(), at_keys(t.active_cells(), at));
    velocity_fresh_ = true;
  }

  // One particle set's stencils, its pairs' transfers and the cells' index.
  struct ParticleStencils {
    std::size_t size = 0;
    Buffer<std::uint32_t> pair_cell;
    Buffer<float> pair_alpha;
    Buffer<double> pair_heat;
    Buffer<TexelMassUnits> pair_eva;
    CellPairIndex<Exec> cells;

    void build(const Exec& exec, const MacGrid& g, const Buffer<Vec3>& position) {
      size = position.size();
      const std::size_t pairs = kStencilSize * size;
      pair_cell.resize(pairs);
      pair_alpha.resize(pairs);
      pair_heat.resize(pairs);
      pair_eva.resize(pairs);
      if (size > 0) exec.parallel_for(size, ComputeStencils{g, Exec::ptr(position), Exec::ptr(pair_cell), Exec::ptr(pair_alpha)});
      cells.build(exec, pair_cell, static_cast<std::uint32_t>(g.cell_count()));
    }
    CellPairs cell_pairs() const {
      if (size == 0) return CellPairs{nullptr, nullptr, nullptr};
      return CellPairs{cells.begin(), Exec::ptr(cells.sorted_pair), Exec::ptr(pair_heat)};
    }
  };

  CouplingSettings settings_;
  ParticleStencils liquid_, rigid_;
  std::vector<TexelVaporExchange<Exec>> texels_;
  Buffer<std::uint32_t> rigid_run_of_cell_;          // per grid cell: the rigid run holding it, or kNoRun
  Buffer<float> temperature_change_;                 // per grid cell
  Buffer<Vec3> cell_velocity_;                       // per grid cell, valid at the active cells
  bool velocity_fresh_ = false;
  Buffer<std::int64_t> net_units_;                   // per liquid active cell
  Buffer<double> vapor_kg_;                          // per grid cell
  Buffer<std::uint32_t> heat_written_, vapor_written_;  // the liquid cells the last step wrote
  Units liquid_to_air_ = 0, texels_to_air_ = 0;
};

}  // namespace dp
