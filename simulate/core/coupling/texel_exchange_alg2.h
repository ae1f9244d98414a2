#pragma once
// Evaporation from and condensation into rigid-surface textures (paper
// Sec. 6.2, Algorithm 2), as written: an estimate per texel-cell pair from
// Eq. 16/17, then the balance w_t^eva (texel non-negative), w_t^cond (texel
// at most m_t^max), w_c^cond (cell non-negative), then the update of both
// sides by the same scaled amounts. Every amount is a whole number of texel
// mass units (coupling/exact_units.h) computed once per pair and gathered
// by the texel and by the cell: the texels lose exactly what the cells gain.
//
// Kernels, one per phase of Alg. 2:
//   EstimateTexelExchange   lines 1-14 (estimate, then w_t^eva, w_t^cond)
//   BalanceCellCondensation lines 15-17 (w_c^cond as num / den)
//   UpdateTexelMass         lines 18-20
//   UpdateCellVapor         lines 21-23 (vapor mass per cell, for AirGrid)
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
DP_HD inline void air_speed_if_needed(const Vec3* cell_velocity, const std::uint32_t* cell, const float* w, float wsum, double b,
                                      double surface_kelvin, bool has_water, AirAtSurfel& a) {
  if (!(b > 0 && has_water && saturation_pressure_at_kelvin(surface_kelvin) > vapor_pressure(a.vapor_density, a.temperature))) return;
  Vec3 v{0, 0, 0};
  for (int k = 0; k < kStencilSize; ++k) v = v + w[k] * cell_velocity[cell[k]];
  a.speed = static_cast<double>(length(v)) / wsum;
}

// Alg. 2 lines 1-14 for texel t: eva and cond per pair, already scaled by
// w_t^eva and w_t^cond.
struct EstimateTexelExchange {
  TexelExchangeView texel;
  AirCellsView air;
  const Vec3* cell_velocity;  // cell-centred, this step
  const std::uint32_t* pair_cell;
  const float* pair_alpha;
  ExchangeParameters p;
  TexelMassUnits* pair_eva;   // m^eva_{c<-t}
  TexelMassUnits* pair_cond;  // m^cond_{t<-c}

  DP_HD void operator()(std::size_t t) const {
    const std::uint32_t* cell = pair_cell + kStencilSize * t;
    TexelMassUnits* eva = pair_eva + kStencilSize * t;
    TexelMassUnits* cond = pair_cond + kStencilSize * t;
    float w[kStencilSize];
    const float wsum = air_weights(air.kind, cell, pair_alpha + kStencilSize * t, w);
    double eva_kg = 0, cond_kg = 0;
    if (wsum > 0) {
      AirAtSurfel a = air_at_stencil(air, cell, w, wsum);
      air_speed_if_needed(cell_velocity, cell, w, wsum, p.coefficients.b, texel.temperature[t], texel.mass[t] > 0, a);
      eva_kg = evaporation_rate(texel.area[t], p.coefficients, texel.temperature[t], a) * p.dt;  // Eq. 16
      if (texel.wetting[t] < p.wet_threshold)
        cond_kg = condensation_rate(texel.area[t], p.coefficients, texel.temperature[t], a) * p.dt;  // Eq. 17
    }
    TexelMassUnits eva_sum = 0, cond_sum = 0;
    for (int k = 0; k < kStencilSize; ++k) {
      const double share = wsum > 0 ? w[k] / wsum : 0.0;
      eva[k] = transfer_units_of_kg(eva_kg * share, p.kg_per_unit);
      cond[k] = transfer_units_of_kg(cond_kg * share, p.kg_per_unit);
      eva_sum += eva[k];
      cond_sum += cond[k];
    }
    const TexelMassUnits m = texel.mass[t], cap = texel.max_mass[t];
    const TexelMassUnits room = cap > m ? cap - m : 0;
    for (int k = 0; k < kStencilSize; ++k) {
      eva[k] = scale_units(eva[k], m, eva_sum);       // w_t^eva = min(m_t / sum eva, 1)
      cond[k] = scale_units(cond[k], room, cond_sum);  // w_t^cond = min((m_t^max - m_t) / sum cond, 1)
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
struct BalanceCellCondensation {
  const std::uint32_t* offset;
  const std::uint32_t* sorted_pair;
  const TexelMassUnits* pair_eva;
  const TexelMassUnits* pair_cond;
  const double* vapor;  // kg/m^3
  double cell_volume;
  double kg_per_unit;
  TexelMassUnits* cond_num;
  TexelMassUnits* cond_den;

  DP_HD void operator()(std::size_t c) const {
    TexelMassUnits e = 0, d = 0;
    for (std::uint32_t q = offset[c]; q < offset[c + 1]; ++q) {
      e += pair_eva[sorted_pair[q]];
      d += pair_cond[sorted_pair[q]];
    }
    const TexelMassUnits m = cell_vapor_units(vapor[c], cell_volume, kg_per_unit);
    const TexelMassUnits avail = m > e ? m - e : 0;
    cond_num[c] = avail < d ? avail : d;
    cond_den[c] = d;
  }
};

// Alg. 2 lines 18-20: m_t += sum_c (cond w_c^cond - eva); the scaled
// condensation is stored back in the texel's own pairs for the cells.
struct UpdateTexelMass {
  const std::uint32_t* pair_cell;
  const TexelMassUnits* pair_eva;
  const TexelMassUnits* cond_num;
  const TexelMassUnits* cond_den;
  TexelMassUnits* pair_cond;
  TexelMassUnits* mass;

  DP_HD void operator()(std::size_t t) const {
    TexelMassUnits gain = 0, loss = 0;
    for (int k = 0; k < kStencilSize; ++k) {
      const std::size_t q = kStencilSize * t + k;
      const std::uint32_t c = pair_cell[q];
      pair_cond[q] = scale_units(pair_cond[q], cond_num[c], cond_den[c]);
      gain += pair_cond[q];
      loss += pair_eva[q];
    }
    mass[t] = mass[t] + gain - loss;  // loss <= m_t and m_t + gain <= max(m_t, m_t^max) by the balance
  }
};

// Alg. 2 lines 21-23: the cell's net gain in units (evaporation in minus
// condensation out), and the same as vapor mass for AirGrid.
struct UpdateCellVapor {
  const std::uint32_t* offset;
  const std::uint32_t* sorted_pair;
  const TexelMassUnits* pair_eva;
  const TexelMassUnits* pair_cond;
  double kg_per_unit;
  std::int64_t* net_units;
  double* vapor_kg;

  DP_HD void operator()(std::size_t c) const {
    TexelMassUnits in = 0, out = 0;
    for (std::uint32_t q = offset[c]; q < offset[c + 1]; ++q) {
      in += pair_eva[sorted_pair[q]];
      out += pair_cond ? pair_cond[sorted_pair[q]] : 0;  // null: evaporation only (particles)
    }
    const std::int64_t net = static_cast<std::int64_t>(in) - static_cast<std::int64_t>(out);
    net_units[c] = net;
    vapor_kg[c] = static_cast<double>(net) * kg_per_unit;
  }
};

}  // namespace dp
