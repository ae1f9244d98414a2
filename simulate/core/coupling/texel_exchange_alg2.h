#pragma once
// Evaporation from and condensation into rigid-surface textures (paper
// Sec. 6.2, Algorithm 2), as written: an estimate per texel-cell pair from
// Eq. 16/17, then the balance w_t^eva (texel non-negative), w_t^cond (texel
// at most m_t^max), w_c^cond (cell non-negative), then the update of both
// sides by the same scaled amounts. Every amount is a whole number of texel
// mass units (coupling/exact_units.h) computed once per pair and gathered
// by the texel and by the cell: the texels lose exactly what the cells gain.
//
// Kernels, in the order they run:
//   EstimateTexelExchange   lines 1-14 (estimate, then w_t^eva, w_t^cond), per texel
//   BalanceCellCondensation lines 15-17 (w_c^cond as num / den) and 21-23
//                           (the cell's net gain), per active cell: the cell
//                           scales its own pairs' condensation by its own w_c^cond
//   UpdateTexelMass         lines 18-20, per texel, the same scaled amounts
//   UpdateCellVapor         lines 21-23 without condensation (particles)
// Cell-side kernels run over the cells some pair names (CellPairIndex's
// runs), writing whole-grid arrays only there.
#include <cstdint>

#include "air/air_grid.h"
#include "coupling/cell_stencil.h"
#include "coupling/evaporation_rate_smith1994.h"
#include "coupling/exact_units.h"

namespace dp {

// The texel side of one rigid's textures, as the kernels read it.
struct TexelExchangeView {
  const Vec3* position;
  const float* area;           // A_t, m^2
  const float* temperature;    // T_t, K
  const float* wetting;        // wetting history, [0, 1]
  const TexelMassUnits* max_mass;
  TexelMassUnits* mass;
};

struct ExchangeParameters {
  EvaporationCoefficients coefficients;
  float dt = 0;                 // s
  double kg_per_unit = 0;       // of one texel mass unit
  // A texel whose wetting history is at least this was touched by liquid
  // within about one wetting decay time and does not condense (Sec. 6.2).
  float wet_threshold = 0.36787944f;  // e^-1
};

// What the air is at a surfel, from the cells of its stencil; the speed is
// left 0 (it is sampled only where it matters, see air_speed_if_needed).
DP_HD inline AirAtSurfel air_at_stencil(const AirCellsView& air, const std::uint32_t* cell, const float* w, float wsum) {
  double rho = 0, excess = 0;
  for (int k = 0; k < kStencilSize; ++k) {
    rho += static_cast<double>(w[k]) * air.vapor[cell[k]];
    excess += static_cast<double>(w[k]) * air.temperature_excess[cell[k]];
  }
  return AirAtSurfel{rho / wsum, air.ambient_temperature + excess / wsum, 0.0};
}

// The air speed enters Eq. 12 only through b, and only for evaporation
// (Eq. 17 drops it) from a surfel that has water. It is the trilinear
// interpolation of the cell-centred velocities (as for the other cell
// quantities, Sec. 6.1) over the surfel's stencil weights.
DP_HD inline double stencil_speed(const Vec3* cell_velocity, const std::uint32_t* cell, const float* w, float wsum) {
  Vec3 v{0, 0, 0};
  for (int k = 0; k < kStencilSize; ++k) v = v + w[k] * cell_velocity[cell[k]];
  return static_cast<double>(length(v)) / wsum;
}

DP_HD inline void air_speed_if_needed(const Vec3* cell_velocity, const std::uint32_t* cell, const float* w, float wsum, double b,
                                      double surface_kelvin, bool has_water, AirAtSurfel& a) {
  if (!(b > 0 && has_water && saturation_pressure_at_kelvin(surface_kelvin) > vapor_pressure(a.vapor_density, a.temperature))) return;
  a.speed = stencil_speed(cell_velocity, cell, w, wsum);
}

// Alg. 2 lines 1-14 for texel t: eva and cond per pair, already scaled by
// w_t^eva and w_t^cond. Eq. 16 and 17 cannot both be positive, and a
// balance factor of 0 (no water: w_t^eva; no room or recently wet: no
// condensation) zeroes a side exactly, so a texel computes only the side
// that can move water, and a dry texel that may not condense computes
// nothing.
struct EstimateTexelExchange {
  TexelExchangeView texel;
  AirCellsView air;
  const Vec3* cell_velocity;  // cell-centred, this step
  const std::uint32_t* pair_cell;  // corner-major (cell_stencil.h)
  const float* pair_alpha;
  std::size_t count;               // texels
  ExchangeParameters p;
  TexelMassUnits* pair_eva;   // m^eva_{c<-t}
  TexelMassUnits* pair_cond;  // m^cond_{t<-c}

  DP_HD void operator()(std::size_t t) const {
    std::uint32_t cell[kStencilSize];
    float alpha[kStencilSize];
    TexelMassUnits eva[kStencilSize], cond[kStencilSize];
    const TexelMassUnits m = texel.mass[t], cap = texel.max_mass[t];
    const TexelMassUnits room = cap > m ? cap - m : 0;
    const bool may_condense = room > 0 && texel.wetting[t] < p.wet_threshold;
    float w[kStencilSize];
    float wsum = 0;
    double eva_kg = 0, cond_kg = 0;
    load_corner_major(pair_cell, pair_alpha, t, count, cell, alpha);
    if (m > 0 || may_condense) wsum = air_weights(air.kind, cell, alpha, w);
    if (wsum > 0) {
      const AirAtSurfel a = air_at_stencil(air, cell, w, wsum);
      const double p_sat = saturation_pressure_at_kelvin(texel.temperature[t]);  // Eq. 11
      const double p_c = vapor_pressure(a.vapor_density, a.temperature);         // Eq. 10
      if (p_sat > p_c) {
        if (m > 0) {
          const double speed = p.coefficients.b > 0 ? stencil_speed(cell_velocity, cell, w, wsum) : 0.0;
          eva_kg = evaporation_rate_at(texel.area[t], p.coefficients, speed, p_sat, p_c) * p.dt;  // Eq. 16
        }
      } else if (may_condense) {
        cond_kg = condensation_rate_at(texel.area[t], p.coefficients, p_sat, p_c) * p.dt;  // Eq. 17
      }
    }
    TexelMassUnits eva_sum = 0, cond_sum = 0;
    for (int k = 0; k < kStencilSize; ++k) {
      const double share = eva_kg > 0 || cond_kg > 0 ? w[k] / wsum : 0.0;
      eva[k] = eva_kg > 0 ? transfer_units_of_kg(eva_kg * share, p.kg_per_unit) : 0;
      cond[k] = cond_kg > 0 ? transfer_units_of_kg(cond_kg * share, p.kg_per_unit) : 0;
      eva_sum += eva[k];
      cond_sum += cond[k];
    }
    if (eva_sum > m)
      for (int k = 0; k < kStencilSize; ++k) eva[k] = scale_units(eva[k], m, eva_sum);  // w_t^eva = min(m_t / sum eva, 1)
    if (cond_sum > room)
      for (int k = 0; k < kStencilSize; ++k) cond[k] = scale_units(cond[k], room, cond_sum);  // w_t^cond = min((m_t^max - m_t) / sum cond, 1)
    for (int k = 0; k < kStencilSize; ++k) {
      pair_eva[corner_major_pair(t, k, count)] = eva[k];
      pair_cond[corner_major_pair(t, k, count)] = cond[k];
    }
  }
};

// The units of vapor a cell holds, rounded down.
DP_HD inline TexelMassUnits cell_vapor_units(double density, double cell_volume, double kg_per_unit) {
  return transfer_units_of_kg(density * cell_volume, kg_per_unit);
}

// Alg. 2 lines 15-17: w_c^cond = min((m_c - sum_t eva) / sum_t cond, 1),
// kept as the fraction num / den (num <= den), clamped at 0. The paper's
// numerator subtracts the cell's incoming evaporation; taken as written it
// keeps a margin (the cell ends with at least twice that evaporation).
// Then lines 21-23 for the cell: its net gain, evaporation in minus its
// pairs' condensation scaled by w_c^cond, the same amounts UpdateTexelMass
// gives the texels.
struct BalanceCellCondensation {
  const std::uint32_t* cell;         // the runs' cells
  const std::uint32_t* begin;        // the runs' first sorted pairs
  const std::uint32_t* sorted_pair;
  const TexelMassUnits* pair_eva;
  const TexelMassUnits* pair_cond;
  const double* vapor;  // kg/m^3
  double cell_volume;
  double kg_per_unit;
  TexelMassUnits* cond_num;  // per grid cell
  TexelMassUnits* cond_den;  // per grid cell
  std::int64_t* net_units;   // per run
  double* vapor_kg;          // per grid cell

  DP_HD void operator()(std::size_t r) const {
    const std::uint32_t c = cell[r];
    TexelMassUnits e = 0, d = 0;
    for (std::uint32_t q = begin[r]; q < begin[r + 1]; ++q) {
      e += pair_eva[sorted_pair[q]];
      d += pair_cond[sorted_pair[q]];
    }
    const TexelMassUnits m = cell_vapor_units(vapor[c], cell_volume, kg_per_unit);
    const TexelMassUnits avail = m > e ? m - e : 0;
    const TexelMassUnits num = avail < d ? avail : d;
    cond_num[c] = num;
    cond_den[c] = d;
    TexelMassUnits out = 0;
    if (d > 0)
      for (std::uint32_t q = begin[r]; q < begin[r + 1]; ++q) out += scale_units(pair_cond[sorted_pair[q]], num, d);
    const std::int64_t net = static_cast<std::int64_t>(e) - static_cast<std::int64_t>(out);
    net_units[r] = net;
    vapor_kg[c] = static_cast<double>(net) * kg_per_unit;
  }
};

// Alg. 2 lines 18-20: m_t += sum_c (cond w_c^cond - eva), with the cell's
// w_c^cond from BalanceCellCondensation.
struct UpdateTexelMass {
  const std::uint32_t* pair_cell;  // corner-major
  std::size_t count;               // texels
  const TexelMassUnits* pair_eva;
  const TexelMassUnits* cond_num;
  const TexelMassUnits* cond_den;
  const TexelMassUnits* pair_cond;
  TexelMassUnits* mass;

  DP_HD void operator()(std::size_t t) const {
    TexelMassUnits gain = 0, loss = 0;
    for (int k = 0; k < kStencilSize; ++k) {
      const std::size_t q = corner_major_pair(t, k, count);
      loss += pair_eva[q];
      if (pair_cond[q] == 0) continue;
      const std::uint32_t c = pair_cell[q];
      gain += scale_units(pair_cond[q], cond_num[c], cond_den[c]);
    }
    mass[t] = mass[t] + gain - loss;  // loss <= m_t and m_t + gain <= max(m_t, m_t^max) by the balance
  }
};

// Lines 21-23 for evaporation alone (particles): the cell's gain in units
// and the same as vapor mass for AirGrid.
struct UpdateCellVapor {
  const std::uint32_t* cell;         // the runs' cells
  const std::uint32_t* begin;
  const std::uint32_t* sorted_pair;
  const TexelMassUnits* pair_eva;
  double kg_per_unit;
  std::int64_t* net_units;  // per run
  double* vapor_kg;         // per grid cell

  DP_HD void operator()(std::size_t r) const {
    TexelMassUnits in = 0;
    for (std::uint32_t q = begin[r]; q < begin[r + 1]; ++q) in += pair_eva[sorted_pair[q]];
    const std::int64_t net = static_cast<std::int64_t>(in);
    net_units[r] = net;
    vapor_kg[cell[r]] = static_cast<double>(net) * kg_per_unit;
  }
};

}  // namespace dp
