#pragma once
// Heat transfer between the air cells and the particles (paper Sec. 5.1,
// Eq. 13-15, Alg. 1 line 13), for liquid and rigid particles alike. The
// heat crossing each particle-cell pair is computed once,
//   Q_ic = dtau k_ic A_i alpha_ic (T_i - T_c) / dx,  k_ic = 4 kappa_i kappa_c / (kappa_i + kappa_c),
// then the particle gathers its pairs (T_i -= sum_c Q_ic / (m_i C_i),
// Eq. 14) and the cell gathers the same pairs (T_c += sum_i Q_ic /
// (rho_c C_c V_c), Eq. 15): what the cells gain the particles lose. The
// paper's Eq. 14-15 as printed carry no length (kappa A dT is W m) and the
// opposite sign to Fourier's law of Eq. 13; Q_ic above is Eq. 13 with the
// temperature gradient taken over one cell size dx (docs/paper-map.md).
#include <cstdint>

#include "air/air_grid.h"
#include "coupling/cell_stencil.h"
#include "coupling/stochastic_rounding.h"
#include "sph/mass_units.h"

namespace dp {

// A set of particles as the heat exchange reads it.
struct HeatSurfels {
  const float* area;             // A_i, m^2 (null: `uniform_area` for all)
  float uniform_area;
  const MassUnits* units;        // liquid: w_i from units (null: rigid)
  const float* volume;           // rigid: Akinci V_b (null: liquid)
  float mass_or_density;         // liquid: m of a full particle; rigid: rho
  float specific_heat;           // C_i
  float conductivity;            // kappa_i
  const std::uint8_t* held;      // rigid particles held at their temperature (may be null)
  const std::uint32_t* id;       // stable ids for the rounding coin (null: the index)
  float* temperature;            // T_i, K

  DP_HD float area_of(std::size_t i) const { return area ? area[i] : uniform_area; }
  DP_HD double heat_capacity(std::size_t i) const {
    const double m = units ? static_cast<double>(weight_of(units[i])) * mass_or_density
                           : static_cast<double>(volume[i]) * mass_or_density;
    return m * specific_heat;
  }
};

struct AirHeatProperties {
  float density = 1.204f;          // rho_c, kg/m^3 (dry air, 20 degC)
  float specific_heat = 1005.0f;   // C_c, J/(kg K)
  float conductivity = 0.0257f;    // kappa_c, W/(m K)
};

// Q_ic per pair (J, positive: into the cell); the particle's own update.
struct ExchangeParticleCellHeat {
  HeatSurfels s;
  AirCellsView air;
  AirHeatProperties a;
  const std::uint32_t* pair_cell;
  const float* pair_alpha;
  float dt;
  std::uint64_t step;
  double* pair_heat;

  DP_HD void operator()(std::size_t i) const {
    const std::uint32_t* cell = pair_cell + kStencilSize * i;
    double* q = pair_heat + kStencilSize * i;
    float w[kStencilSize];
    const float wsum = air_weights(air.kind, cell, pair_alpha + kStencilSize * i, w);
    const double k = s.conductivity + a.conductivity > 0
                         ? 4.0 * s.conductivity * a.conductivity / (s.conductivity + a.conductivity) : 0.0;
    const double c = wsum > 0 ? dt * k * s.area_of(i) / (air.grid.dx * wsum) : 0.0;
    const double ti = s.temperature[i];
    double total = 0;
    for (int n = 0; n < kStencilSize; ++n) {
      const double tc = air.ambient_temperature + static_cast<double>(air.temperature_excess[cell[n]]);
      q[n] = c * w[n] * (ti - tc);
      total += q[n];
    }
    if (s.held && s.held[i]) return;  // a held particle is a heat source: its temperature stays
    // The particle keeps its temperature in float, rounded stochastically
    // (a step's change is often below one ulp); the pairs carry the heat of
    // the change float actually made, so the cells get exactly what the
    // particle lost.
    const double capacity = s.heat_capacity(i);
    const std::uint32_t who = s.id ? s.id[i] : static_cast<std::uint32_t>(i);
    const float updated = stochastic_round_to_float(ti - total / capacity, rounding_hash(who, step ^ (1ull << 63)));  // a coin apart from evaporation's
    const double realised = (ti - static_cast<double>(updated)) * capacity;
    const double scale = total != 0 ? realised / total : 0.0;
    for (int n = 0; n < kStencilSize; ++n) q[n] *= scale;
    s.temperature[i] = updated;
  }
};

// The pairs of one particle set, by active cell (CellPairIndex's runs).
struct CellPairs {
  const std::uint32_t* begin;        // null: the set is empty
  const std::uint32_t* sorted_pair;
  const double* pair_heat;
  DP_HD double sum(std::uint32_t run) const {
    double q = 0;
    for (std::uint32_t p = begin[run]; p < begin[run + 1]; ++p) q += pair_heat[sorted_pair[p]];
    return q;
  }
};

inline constexpr std::uint32_t kNoRun = 0xFFFFFFFFu;

// Eq. 15: each cell gathers the heat of its liquid and rigid pairs, as a
// temperature change. Run over the rigid particles' cells first (their heat
// alone), then over the liquid particles' cells, which add the rigid pairs
// of the same cell found through `rigid_run_of_cell`.
struct GatherCellHeat {
  const std::uint32_t* cell;               // the runs' cells
  CellPairs own;                           // the set whose runs these are
  CellPairs rigid;                         // liquid pass: the rigid set (begin null: none)
  const std::uint32_t* rigid_run_of_cell;  // liquid pass: per grid cell, its rigid run or kNoRun
  double heat_capacity;                    // rho_c C_c V_c
  float* temperature_change;               // per grid cell

  DP_HD void operator()(std::size_t r) const {
    const std::uint32_t c = cell[r];
    double q = own.sum(static_cast<std::uint32_t>(r));
    if (rigid.begin) {
      const std::uint32_t rr = rigid_run_of_cell[c];
      q = q + (rr != kNoRun ? rigid.sum(rr) : 0.0);
    }
    temperature_change[c] = static_cast<float>(q / heat_capacity);
  }
};

// Per grid cell, the run of a CellPairIndex that holds it.
struct MarkRunOfCell {
  const std::uint32_t* cell;
  std::uint32_t* run_of_cell;
  DP_HD void operator()(std::size_t r) const { run_of_cell[cell[r]] = static_cast<std::uint32_t>(r); }
};

}  // namespace dp
