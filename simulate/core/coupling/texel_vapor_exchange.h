#pragma once
// Texels <-> air (Alg. 1 line 16, paper Alg. 2) for one rigid's textures on
// a backend: the texel <-> cell neighbourhoods built once (rigids and their
// textures are static, Sec. 4.4), and each step the four phases of
// texel_exchange_alg2.h, the cells' vapor change handed to the air grid.
#include <cstdint>

#include "air/air_grid.h"
#include "coupling/cell_stencil.h"
#include "coupling/exact_units.h"
#include "coupling/texel_exchange_alg2.h"

namespace dp {

template <class Exec>
class TexelVaporExchange {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

 public:
  // `texel_normal` empty: stencils at the texels themselves (tests of Alg. 2
  // alone); otherwise one cell in front of them (ComputeStencilsInFront).
  void prepare(const Exec& exec, const MacGrid& grid, const Buffer<Vec3>& texel_position, const Buffer<Vec3>& texel_normal = {}) {
    texels_ = texel_position.size();
    const std::size_t pairs = kStencilSize * texels_;
    pair_cell_.resize(pairs);
    pair_alpha_.resize(pairs);
    pair_eva_.resize(pairs);
    pair_cond_.resize(pairs);
    if (texel_normal.size() == texels_)
      exec.parallel_for(texels_, ComputeStencilsInFront{grid, Exec::ptr(texel_position), Exec::ptr(texel_normal), Exec::ptr(pair_cell_),
                                                        Exec::ptr(pair_alpha_), texels_});
    else
      exec.parallel_for(texels_, ComputeTexelStencils{grid, Exec::ptr(texel_position), Exec::ptr(pair_cell_), Exec::ptr(pair_alpha_),
                                                      texels_});
    cells_.build(exec, pair_cell_);
    for (auto* b : {&cond_num_, &cond_den_}) b->resize(grid.cell_count());
    net_units_.resize(cells_.active_cells());
    // Written only at the active cells, which never change: the rest stays 0.
    vapor_kg_.assign(grid.cell_count(), 0.0);
  }

  // The cells the texels exchange with (their stencils' cells), ascending.
  const std::uint32_t* active_cells() const { return cells_.cell(); }
  std::size_t active_cell_count() const { return cells_.active_cells(); }

  // One step of Alg. 2; returns the units the air gained (negative: lost).
  // `cell_velocity`: the cell-centred air velocity of this step.
  std::int64_t exchange(const Exec& exec, const TexelExchangeView& texel, AirGrid<Exec>& air, const Vec3* cell_velocity,
                        const ExchangeParameters& p) {
    if (texels_ == 0) return 0;
    const MacGrid& g = air.grid();
    const std::size_t active = cells_.active_cells();
    const AirCellsView view = air.view();
    exec.parallel_for(texels_, EstimateTexelExchange{texel, view, cell_velocity, Exec::ptr(pair_cell_), Exec::ptr(pair_alpha_), texels_, p,
                                                     Exec::ptr(pair_eva_), Exec::ptr(pair_cond_)});
    exec.parallel_for(active, BalanceCellCondensation{cells_.cell(), cells_.begin(), Exec::ptr(cells_.sorted_pair), Exec::ptr(pair_eva_),
                                                      Exec::ptr(pair_cond_), view.vapor, static_cast<double>(g.cell_volume()),
                                                      p.kg_per_unit, Exec::ptr(cond_num_), Exec::ptr(cond_den_),
                                                      Exec::ptr(net_units_), Exec::ptr(vapor_kg_)});
    exec.parallel_for(texels_, UpdateTexelMass{Exec::ptr(pair_cell_), texels_, Exec::ptr(pair_eva_), Exec::ptr(cond_num_),
                                               Exec::ptr(cond_den_), Exec::ptr(pair_cond_), texel.mass});
    air.add_cell_sources(exec, Exec::ptr(vapor_kg_), nullptr);
    return exact_units_sum(exec, active, Exec::ptr(net_units_));
  }

 private:
  std::size_t texels_ = 0;
  Buffer<std::uint32_t> pair_cell_;
  Buffer<float> pair_alpha_;
  Buffer<TexelMassUnits> pair_eva_, pair_cond_, cond_num_, cond_den_;
  Buffer<std::int64_t> net_units_;  // per active cell
  Buffer<double> vapor_kg_;         // per grid cell
  CellPairIndex<Exec> cells_;
};

}  // namespace dp
