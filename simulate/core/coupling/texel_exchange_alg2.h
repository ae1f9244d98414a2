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
//   EstimateTexelExchange   lines 1-14 (estimate, then w_t^eva, w_t^cond), per
//                           texel, and lines 18-20 for an evaporating texel
//   BalanceCellCondensation lines 15-17 (w_c^cond as num / den) and 21-23
//                           (the cell's net gain), per active cell: the cell
//                           scales its own pairs' condensation by its own w_c^cond
//   UpdateTexelMass         lines 18-20 for a condensing texel, the same scaled amounts
//   UpdateCellVapor         lines 21-23 without condensation (particles)
// Cell-side kernels run over the cells some pair names (CellPairIndex's
// runs), writing whole-grid arrays only there.
//
// A texel either evaporates or condenses (Eq. 16 and 17 cannot both be
// positive), so a pair keeps one signed amount, PairFlow, and an
// evaporating texel's loss, which no cell's factor scales, is final in the
// estimate: only condensing texels wait for their cells' w_c^cond.
// Texel-side kernels visit the texels in an order of their own (`order`:
// position -> texel, TexelVaporExchange::order_by_first_cell); pairs and
// per-texel scratch are kept in that order.
#include <cstdint>

#include "air/air_grid.h"
#include "coupling/cell_stencil.h"
#include "coupling/evaporation_rate_smith1994.h"
#include "coupling/exact_units.h"
#include "math/keep_if.h"

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

// m^eva_{c<-t} (> 0, to the cell) or -m^cond_{t<-c} (< 0, to the texel) of
// one pair, in texel units (each below kMaxTransferUnits).
using PairFlow = std::int64_t;

DP_HD inline TexelMassUnits condensation_of(PairFlow f) { return f < 0 ? static_cast<TexelMassUnits>(-f) : 0; }

// Eq. 11 at each texel's temperature, kept with the temperature it is of:
// texel temperatures change only with the rigids' (held rigids never), and
// the same float gives the same pressure, so the exp is taken again only
// for a texel whose temperature changed.
struct SaturationPressureCache {
  float* kelvin;    // NaN: none yet
  double* pressure;  // Pa
  DP_HD double at(std::size_t t, float temperature) const {
    if (kelvin[t] == temperature) return pressure[t];
    kelvin[t] = temperature;
    pressure[t] = saturation_pressure_at_kelvin(temperature);
    return pressure[t];
  }
};

struct ExchangeParameters {
  EvaporationCoefficients coefficients;
  float dt = 0;                 // s
  double kg_per_unit = 0;       // of one texel mass unit
  // A texel whose wetting history is at least this was touched by liquid
  // within about one wetting decay time and does not condense (Sec. 6.2).
  float wet_threshold = 0.36787944f;  // e^-1
};

// How many texels ahead the texel kernels ask for a texel's data
// (EstimateTexelExchange, UpdateTexelMass): 16, 32 and 64 measured the same.
inline constexpr std::size_t kTexelPrefetchAhead = 16;

// A corner of weight 0 (a rigid cell: four of the eight for a plate's
// texels) adds exactly +0 to a stencil's sums: they start at +0 and never
// turn -0, and the air's values are finite (the step that makes one stops
// the run with the same error either way). The sums skip it, and so do the
// pairs' shares (0 units): two divisions and six products fewer per corner.
//
// What the air is at a surfel, from the cells of its stencil; the speed is
// left 0 (it is sampled only where it matters, see air_speed_if_needed).
// kUnitSum: wsum is 1 (over_weight_sum).
template <bool kUnitSum = false>
DP_HD inline AirAtSurfel air_at_stencil(const AirCellsView& air, const std::uint32_t* cell, const float* w, float wsum) {
  double rho = 0, excess = 0;
  for (int k = 0; k < kStencilSize; ++k) {
    if (w[k] == 0) continue;
    rho += static_cast<double>(w[k]) * air.vapor[cell[k]];
    excess += static_cast<double>(w[k]) * air.temperature_excess[cell[k]];
  }
  return AirAtSurfel{over_weight_sum<kUnitSum>(rho, wsum), air.ambient_temperature + over_weight_sum<kUnitSum>(excess, wsum), 0.0};
}

// The air speed enters Eq. 12 only through b, and only for evaporation
// (Eq. 17 drops it) from a surfel that has water. It is the trilinear
// interpolation of the cell-centred velocities (as for the other cell
// quantities, Sec. 6.1) over the surfel's stencil weights.
// (Per component: the same sums as Vec3's operators, which the compiler
// otherwise keeps packing and unpacking.)
template <bool kUnitSum = false>
DP_HD inline double stencil_speed(const Vec3* cell_velocity, const std::uint32_t* cell, const float* w, float wsum) {
  float x = 0, y = 0, z = 0;
  for (int k = 0; k < kStencilSize; ++k) {
    if (w[k] == 0) continue;
    const Vec3 c = cell_velocity[cell[k]];
    x = x + w[k] * c.x;
    y = y + w[k] * c.y;
    z = z + w[k] * c.z;
  }
  return over_weight_sum<kUnitSum>(static_cast<double>(length(Vec3{x, y, z})), wsum);
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
// nothing. An evaporating texel loses its pairs' sum here (lines 18-20: no
// cell factor scales evaporation); a condensing one is flagged for
// UpdateTexelMass.
struct EstimateTexelExchange {
  TexelExchangeView texel;
  const std::uint32_t* order;
  AirCellsView air;
  const Vec3* cell_velocity;  // cell-centred, this step
  const std::uint32_t* pair_cell;  // corner-major (cell_stencil.h)
  const float* pair_alpha;
  std::size_t count;               // texels
  ExchangeParameters p;
  SaturationPressureCache saturation;
  PairFlow* pair_flow;
  std::uint8_t* condensing;  // per texel: some pair gives it water

  // DP_HD_INLINE here and in exchange and signed_exchange_kg: g++ left this
  // functor out of line, so the CPU ran it as baseline code and not in the
  // launcher's AVX2 copy (SCA Logo Tex's Eva 57.7 -> 51.9 ms, the same bits).
  DP_HD_INLINE void operator()(std::size_t t) const {
    prefetch_texel(t + kTexelPrefetchAhead);
    const std::uint32_t x = order[t];
    const TexelMassUnits m = texel.mass[x], cap = texel.max_mass[x];
    const TexelMassUnits room = cap > m ? cap - m : 0;
    const bool may_condense = room > 0 && texel.wetting[x] < p.wet_threshold;
    std::uint32_t cell[kStencilSize];
    float w[kStencilSize];
    float wsum = 0;
    if (m > 0 || may_condense) {
      float alpha[kStencilSize];
      load_corner_major(pair_cell, pair_alpha, t, count, cell, alpha);
      wsum = air_weights(air.kind, cell, alpha, w);
    }
    if (wsum == 1.0f)
      exchange<true>(t, x, m, room, may_condense, cell, w, wsum);
    else
      exchange<false>(t, x, m, room, may_condense, cell, w, wsum);
  }

  // The texels are visited in exchange order, which jumps between the rows
  // of the atlas every few texels: their data are asked for
  // kTexelPrefetchAhead texels ahead (the glass's estimate waited on those loads).
  DP_HD_INLINE void prefetch_texel(std::size_t t) const {
    if (t >= count) return;
    const std::uint32_t y = order[t];
    prefetch(texel.mass + y);
    prefetch(texel.max_mass + y);
    prefetch(texel.wetting + y);
    prefetch(texel.temperature + y);
    prefetch(texel.area + y);
  }

  // The rest of texel x's (at position t) estimate, from its stencil's
  // weights (wsum 0: none, or nothing to move); kUnitSum: wsum is 1.
  template <bool kUnitSum>
  DP_HD_INLINE void exchange(std::size_t t, std::uint32_t x, TexelMassUnits m, TexelMassUnits room, bool may_condense,
                             const std::uint32_t* cell, const float* w, float wsum) const {
    // Eq. 16 (> 0) or Eq. 17 (< 0) times dt: at most one side is non-zero.
    const double kg = wsum > 0 ? signed_exchange_kg<kUnitSum>(t, x, cell, w, wsum, m > 0, may_condense) : 0.0;
    // The pairs' shares, each rounded down, then w_t^eva or w_t^cond.
    TexelMassUnits units[kStencilSize];
    TexelMassUnits sum = 0;
    const double amount = kg > 0 ? kg : -kg;
    for (int k = 0; k < kStencilSize; ++k) {
      units[k] = kg != 0 && w[k] != 0 ? transfer_units_of_kg(amount * static_cast<double>(over_weight_sum<kUnitSum>(w[k], wsum)), p.kg_per_unit) : 0;
      sum += units[k];
    }
    const TexelMassUnits bound = kg > 0 ? m : room;
    if (sum > bound) {
      TexelMassUnits scaled = 0;
      for (int k = 0; k < kStencilSize; ++k) {
        units[k] = scale_units(units[k], bound, sum);  // w_t^eva = min(m_t / sum eva, 1), w_t^cond = min((m_t^max - m_t) / sum cond, 1)
        scaled += units[k];
      }
      sum = scaled;
    }
    for (int k = 0; k < kStencilSize; ++k)
      pair_flow[corner_major_pair(t, k, count)] = kg > 0 ? static_cast<PairFlow>(units[k]) : -static_cast<PairFlow>(units[k]);
    if (kg > 0 && sum > 0) texel.mass[x] = m - sum;  // sum <= m_t by w_t^eva
    condensing[t] = kg < 0 && sum > 0;
  }

  // Texel x's (at position t) Eq. 16 rate (positive) or minus its Eq. 17
  // rate, times dt, kg; 0 when the side the pressures pick cannot move water.
  template <bool kUnitSum>
  DP_HD_INLINE double signed_exchange_kg(std::size_t t, std::uint32_t x, const std::uint32_t* cell, const float* w, float wsum,
                                         bool has_water, bool may_condense) const {
    const AirAtSurfel a = air_at_stencil<kUnitSum>(air, cell, w, wsum);
    const double p_sat = saturation.at(t, texel.temperature[x]);        // Eq. 11
    const double p_c = vapor_pressure(a.vapor_density, a.temperature);  // Eq. 10
    if (p_sat > p_c) {
      if (!has_water) return 0;
      const double speed = p.coefficients.b > 0 ? stencil_speed<kUnitSum>(cell_velocity, cell, w, wsum) : 0.0;
      return evaporation_rate_at(texel.area[x], p.coefficients, speed, p_sat, p_c) * p.dt;  // Eq. 16
    }
    if (!may_condense) return 0;
    return -(condensation_rate_at(texel.area[x], p.coefficients, p_sat, p_c) * p.dt);  // Eq. 17
  }
};

// The units of vapor a cell holds, rounded down.
DP_HD inline TexelMassUnits cell_vapor_units(double density, double cell_volume, double kg_per_unit) {
  return transfer_units_of_kg(density * cell_volume, kg_per_unit);
}

// A cell's sums over its pairs, a stretch of consecutive pairs at a time:
// sum eva - sum cond (unsigned sums wrap alike in any order, so
// e = flow + condensation exactly), sum cond, and the bits of the warmest
// condensing texel's p_sat (non-negative doubles order as their bits).
// Without a branch, so that g++ adds four pairs at a time: the loop with a
// branch per pair waited on each load (18 ms of SCA Logo Tex's Eva).
struct CellPairSums {
  TexelMassUnits flow = 0, condensation = 0;
  std::int64_t warmest_bits = 0;

  DP_HD_INLINE void add(const PairFlow* f, const double* saturation_pressure, std::size_t n) {
    TexelMassUnits in = flow, out = condensation;
    std::int64_t warmest = warmest_bits;
    for (std::size_t i = 0; i < n; ++i) {
      const PairFlow x = f[i];
      const std::int64_t condensing = x < 0 ? -1 : 0;  // all ones where the pair condenses
      in += static_cast<TexelMassUnits>(x);
      out += static_cast<TexelMassUnits>(-x) & static_cast<TexelMassUnits>(condensing);
      const std::int64_t bits = bits_of(saturation_pressure[i]) & condensing;
      warmest = warmest > bits ? warmest : bits;
    }
    flow = in;
    condensation = out;
    warmest_bits = warmest;
  }
};

// Alg. 2 lines 15-17: w_c^cond = min((m_c - m_c^sat - sum_t eva) / sum_t cond, 1),
// kept as the fraction num / den (num <= den), clamped at 0. The paper's
// numerator subtracts the cell's incoming evaporation; taken as written it
// keeps a margin (the cell ends with at least twice that evaporation).
//
// m_c^sat, the cell's vapor at the saturation pressure of its warmest
// condensing texel, is ours (docs/paper-map.md, departures): Eq. 17 is
// explicit in p_c, so a step whose condensation exceeds the cell's excess
// over saturation carries the cell past equilibrium, and the paper's floor
// (m_c >= 0) lets it empty the cell. With phase change sped up (the mirror's
// x7700) that happened every other step: the cells in front of a 4 degC
// mirror were emptied, the wet mirror then evaporated into them, and so on.
// Condensation stops at saturation instead, as the rate law says it does;
// where a step condenses less than the excess (physical rates) nothing changes.
//
// Then lines 21-23 for the cell: its net gain, evaporation in minus its
// pairs' condensation scaled by w_c^cond. The scaled amounts are written
// back into the pairs (computed once), for UpdateTexelMass to give the
// texels. The cell reads its pairs by stretches of consecutive pairs
// (CellPairIndex::build_stretches); pair q is texel position q mod texels.
struct BalanceCellCondensation {
  const std::uint32_t* cell;  // the runs' cells
  PairStretches pairs;
  PairFlow* pair_flow;
  std::size_t texels;
  const double* saturation_pressure;  // per texel position, this step's (SaturationPressureCache)
  AirCellsView air;
  double cell_volume;
  double kg_per_unit;
  std::int64_t* net_units;  // per run
  double* vapor_kg;         // per grid cell

  DP_HD void operator()(std::size_t r) const {
    const std::uint32_t c = cell[r];
    CellPairSums sums;
    for (std::uint32_t s = pairs.run_first[r]; s < pairs.run_first[r + 1]; ++s) {
      // Pair q is texel position q mod texels; a stretch may run on from
      // the last position of one corner to the first of the next.
      std::size_t q = pairs.first_pair[s], t = q % texels;
      for (std::size_t left = pairs.begin[s + 1] - pairs.begin[s]; left > 0; t = 0) {
        const std::size_t n = left < texels - t ? left : texels - t;
        sums.add(pair_flow + q, saturation_pressure + t, n);
        q += n;
        left -= n;
      }
    }
    const TexelMassUnits flow = sums.flow, d = sums.condensation;
    const double p_sat = from_bits(sums.warmest_bits);
    const TexelMassUnits e = flow + d;
    TexelMassUnits out = d;
    if (d > 0) {
      const double kelvin = static_cast<double>(air.ambient_temperature) + static_cast<double>(air.temperature_excess[c]);
      const TexelMassUnits m = cell_vapor_units(air.vapor[c], cell_volume, kg_per_unit);
      const TexelMassUnits m_sat = cell_vapor_units(vapor_density_at_pressure(p_sat, kelvin), cell_volume, kg_per_unit);
      const TexelMassUnits avail = m > e && m - e > m_sat ? m - e - m_sat : 0;  // m - e - m_sat, clamped at 0 without overflow
      if (avail < d) out = scale_cell_condensation(r, avail, d);
    }
    const std::int64_t net = static_cast<std::int64_t>(e) - static_cast<std::int64_t>(out);
    net_units[r] = net;
    vapor_kg[c] = static_cast<double>(net) * kg_per_unit;
  }

  // Each condensing pair's units times num / den, rounded down, written back;
  // returns their sum (at most num: the sum of floors).
  DP_HD TexelMassUnits scale_cell_condensation(std::size_t r, TexelMassUnits num, TexelMassUnits den) const {
    const UnitScale scale(num, den);
    TexelMassUnits out = 0;
    for (std::uint32_t s = pairs.run_first[r]; s < pairs.run_first[r + 1]; ++s) {
      PairFlow* f = pair_flow + pairs.first_pair[s];
      for (std::uint32_t i = 0, n = pairs.begin[s + 1] - pairs.begin[s]; i < n; ++i) {
        if (f[i] >= 0) continue;
        const TexelMassUnits scaled = scale(condensation_of(f[i]));
        f[i] = -static_cast<PairFlow>(scaled);
        out += scaled;
      }
    }
    return out;
  }
};

// Alg. 2 lines 18-20 for a condensing texel: m_t += sum_c cond w_c^cond,
// the amounts BalanceCellCondensation scaled (it has no evaporation:
// EstimateTexelExchange).
struct UpdateTexelMass {
  const std::uint32_t* order;  // position -> texel
  std::size_t count;           // texels
  const PairFlow* pair_flow;
  const std::uint8_t* condensing;
  TexelMassUnits* mass;

  DP_HD void operator()(std::size_t t) const {
    const std::size_t ahead = t + kTexelPrefetchAhead;
    if (ahead < count && condensing[ahead]) prefetch(mass + order[ahead]);
    if (!condensing[t]) return;
    TexelMassUnits gain = 0;
    for (int k = 0; k < kStencilSize; ++k) gain += condensation_of(pair_flow[corner_major_pair(t, k, count)]);
    mass[order[t]] += gain;  // m_t + gain <= max(m_t, m_t^max) by the balance
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
