#pragma once
// Particle evaporation (paper Sec. 6.2 "Evaporation and condensation of
// particles", Alg. 1 line 15): a liquid particle at the surface loses mass
// by Eq. 16 to the cells of its stencil, balanced like Alg. 2's w_t^eva so
// that it never gives more than it has, applied to its integer mass units
// (sph/mass_units.h) instead of its mass. Particles only evaporate;
// condensation reaches the liquid through the textures (Sec. 6.2).
//
// A step's loss is usually a fraction of one mass unit (2^-24 of a
// particle: 6e-11 kg at 1 cm spacing, against ~1e-11 kg per step at
// 20 degC). Rounding it down would stop evaporation altogether; it is
// rounded up with probability equal to the fraction instead, from a hash
// of the particle's id and the step, so the expected loss is Eq. 16's, the
// transfer stays a whole number of units and the run stays deterministic.
// The particle's whole units, in texel units, are then shared among its
// cells in proportion to the estimate; a particle left with no units is
// removed by the adaptivity step (Alg. 1 line 18), all its water in the air.
#include <cstdint>

#include "air/air_grid.h"
#include "coupling/cell_stencil.h"
#include "coupling/evaporation_rate_smith1994.h"
#include "coupling/exact_units.h"
#include "coupling/stochastic_rounding.h"
#include "coupling/texel_exchange_alg2.h"
#include "sph/mass_units.h"

namespace dp {

struct EvaporateParticles {
  AirCellsView air;
  const Vec3* cell_velocity;  // cell-centred, this step
  const std::uint32_t* pair_cell;
  const float* pair_alpha;
  const float* area;         // A_i (Orthmann-style estimate, sph/surface_area_orthmann2013.h)
  float* temperature;        // T_i, K (lowered by the latent heat when that is on)
  const std::uint32_t* id;
  EvaporationCoefficients coefficients;
  float dt;
  double kg_per_unit;        // of a texel unit
  std::uint64_t step;
  MassUnits* units;
  TexelMassUnits* pair_eva;  // per pair, texel units
  // Beyond the paper (issue #5): evaporation takes L per kg from the
  // particle, T_i -= L dm / (m_i C). 0: off, as in the paper.
  float latent_heat_over_specific_heat = 0;  // L / C_i, K

  // Always inlined, into the launcher's AVX2 copy too (docs/architecture.md).
  DP_HD_INLINE void operator()(std::size_t i) const {
    const std::uint32_t* cell = pair_cell + kStencilSize * i;
    TexelMassUnits* eva = pair_eva + kStencilSize * i;
    float w[kStencilSize];
    const float wsum = air_weights(air.kind, cell, pair_alpha + kStencilSize * i, w);
    TexelMassUnits estimate = 0;
    if (wsum > 0 && area[i] > 0) {
      AirAtSurfel a = air_at_stencil(air, cell, w, wsum);
      air_speed_if_needed(cell_velocity, cell, w, wsum, coefficients.b, temperature[i], units[i] > 0, a);
      estimate = transfer_units_of_kg(evaporation_rate(area[i], coefficients, temperature[i], a) * dt, kg_per_unit);  // Eq. 16
    }
    // Whole mass units, stochastically rounded, at most what the particle has (w^eva).
    TexelMassUnits whole = estimate >> kTexelUnitShift;
    const std::uint32_t fraction = static_cast<std::uint32_t>(estimate & (kTexelUnitsPerMassUnit - 1));
    if (rounding_hash(id[i], step) < fraction) ++whole;
    if (whole > units[i]) whole = units[i];
    units[i] -= static_cast<MassUnits>(whole);
    if (latent_heat_over_specific_heat > 0 && whole > 0 && units[i] > 0)
      temperature[i] -= latent_heat_over_specific_heat * static_cast<float>(static_cast<double>(whole) / units[i]);
    share(whole << kTexelUnitShift, w, wsum, eva);
  }

  // `total` split over the pairs by weight: floors, the rest to the
  // heaviest pair, so the pairs add up to `total` exactly.
  DP_HD static void share(TexelMassUnits total, const float* w, float wsum, TexelMassUnits* eva) {
    TexelMassUnits given = 0;
    int heaviest = 0;
    for (int k = 0; k < kStencilSize; ++k) {
      eva[k] = total > 0 && wsum > 0 ? static_cast<TexelMassUnits>(static_cast<double>(total) * (w[k] / wsum)) : 0;
      if (eva[k] > total - given) eva[k] = total - given;
      given += eva[k];
      if (w[k] > w[heaviest]) heaviest = k;
    }
    eva[heaviest] += total - given;
  }
};

}  // namespace dp
