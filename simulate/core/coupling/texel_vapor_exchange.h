#pragma once
// Texels <-> air (Alg. 1 line 16, paper Alg. 2) for one rigid's textures on
// a backend: the texel <-> cell neighbourhoods built once (rigids and their
// textures are static, Sec. 4.4), and each step the four phases of
// texel_exchange_alg2.h, the cells' vapor change handed to the air grid.
#include <cstdint>
#include <limits>

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
    Buffer<std::uint32_t> atlas_cell(pairs);
    Buffer<float> atlas_alpha(pairs);
    if (texel_normal.size() == texels_)
      exec.parallel_for(texels_, ComputeStencilsInFront{grid, Exec::ptr(texel_position), Exec::ptr(texel_normal), Exec::ptr(atlas_cell),
                                                        Exec::ptr(atlas_alpha), texels_});
    else
      exec.parallel_for(texels_, ComputeTexelStencils{grid, Exec::ptr(texel_position), Exec::ptr(atlas_cell), Exec::ptr(atlas_alpha),
                                                      texels_});
    order_by_first_cell(exec, atlas_cell);
    pair_cell_.resize(pairs);
    pair_alpha_.resize(pairs);
    if (texels_ > 0)
      exec.parallel_for(texels_, PermuteCornerMajor{Exec::ptr(order_), texels_, Exec::ptr(atlas_cell), Exec::ptr(atlas_alpha),
                                                    Exec::ptr(pair_cell_), Exec::ptr(pair_alpha_)});
    pair_flow_.resize(pairs);
    condensing_.resize(texels_);
    saturation_kelvin_.assign(texels_, std::numeric_limits<float>::quiet_NaN());
    saturation_pressure_.resize(texels_);
    cells_.build(exec, pair_cell_, static_cast<std::uint32_t>(grid.cell_count()));
    cells_.build_stretches(exec);
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
    const SaturationPressureCache saturation{Exec::ptr(saturation_kelvin_), Exec::ptr(saturation_pressure_)};
    exec.parallel_for(texels_, EstimateTexelExchange{texel, Exec::ptr(order_), view, cell_velocity, Exec::ptr(pair_cell_),
                                                     Exec::ptr(pair_alpha_), texels_, p, saturation, Exec::ptr(pair_flow_),
                                                     Exec::ptr(condensing_)});
    exec.parallel_for_by_work(active, PairsBeforeRun{cells_.stretches()},
                              BalanceCellCondensation{cells_.cell(), cells_.stretches(), Exec::ptr(pair_flow_), texels_,
                                                      Exec::ptr(saturation_pressure_), view, static_cast<double>(g.cell_volume()),
                                                      p.kg_per_unit, Exec::ptr(net_units_), Exec::ptr(vapor_kg_)});
    exec.parallel_for(texels_, UpdateTexelMass{Exec::ptr(order_), texels_, Exec::ptr(pair_flow_), Exec::ptr(condensing_), texel.mass});
    air.add_vapor_at(exec, cells_.cell(), active, Exec::ptr(vapor_kg_));
    return exact_units_sum(exec, active, Exec::ptr(net_units_));
  }

 private:
  // The exchange visits the texels in the order of their stencils' first
  // cell (stable: atlas order within a cell): texels sharing all eight
  // cells are neighbours, so each cell's pairs form a few long stretches
  // (about one per corner) instead of one per atlas row. Results do not
  // depend on it: texels are independent and cells sum integers.
  void order_by_first_cell(const Exec& exec, const Buffer<std::uint32_t>& atlas_cell) {
    Buffer<std::uint32_t> first_cell(atlas_cell.begin(), atlas_cell.begin() + static_cast<std::ptrdiff_t>(texels_));  // corner 0
    order_.resize(texels_);
    if (texels_ == 0) return;
    exec.parallel_for(texels_, Iota{Exec::ptr(order_)});
    exec.sort_by_key(first_cell, order_);
  }

  std::size_t texels_ = 0;
  Buffer<std::uint32_t> order_;  // exchange order -> texel (order_by_first_cell)
  Buffer<std::uint32_t> pair_cell_;
  Buffer<float> pair_alpha_;
  Buffer<PairFlow> pair_flow_;
  Buffer<std::uint8_t> condensing_;  // per texel
  Buffer<float> saturation_kelvin_;  // SaturationPressureCache
  Buffer<double> saturation_pressure_;
  Buffer<std::int64_t> net_units_;  // per active cell
  Buffer<double> vapor_kg_;         // per grid cell
  CellPairIndex<Exec> cells_;
};

}  // namespace dp
