#pragma once
// Water held by a texel (paper Sec. 4.3, the mass texture m_t), as an integer
// count of texel mass units. A texel unit is 2^-32 of a liquid particle's
// mass unit (sph/mass_units.h), so
//   * texel <-> particle transfers (emission, Sec. 6.2) convert exactly:
//     a particle of U units is U * 2^32 texel units;
//   * per-step condensation onto one texel, typically 1e-14 kg, is still
//     millions of units (one unit is 1.4e-20 kg at 1 cm spacing), where the
//     liquid's own unit (6e-11 kg) would round it to nothing;
//   * sums over texels are exact and order-independent (DESIGN §6).
// 64 bits hold 256 full particles per texel, far above what a texel's
// m_t^max allows in practice; texel_units_of_kg reports when they do not.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "backend/host_device.h"
#include "sph/mass_units.h"

namespace dp {

using TexelMassUnits = std::uint64_t;

inline constexpr int kTexelUnitShift = 32;  // texel units per liquid mass unit = 2^32
inline constexpr TexelMassUnits kTexelUnitsPerMassUnit = TexelMassUnits{1} << kTexelUnitShift;

// kg of one texel unit, for particles of `particle_mass` kg (rho0 spacing^3).
inline double kg_per_texel_unit(double particle_mass) {
  return particle_mass / (static_cast<double>(kFullParticleUnits) * static_cast<double>(kTexelUnitsPerMassUnit));
}

// The largest mass one texel can hold, in kg.
inline double max_texel_mass_kg(double particle_mass) { return 18446744073709549568.0 * kg_per_texel_unit(particle_mass); }

// kg -> units, rounded down so a cap is never exceeded; throws when the mass
// does not fit in 64 bits.
inline TexelMassUnits texel_units_of_kg(double kg, double particle_mass) {
  if (!(kg >= 0)) throw std::invalid_argument("texel mass must be non-negative, found " + std::to_string(kg) + " kg");
  if (kg > max_texel_mass_kg(particle_mass))
    throw std::invalid_argument("texel mass " + std::to_string(kg) + " kg exceeds what a texel can hold (" +
                                std::to_string(max_texel_mass_kg(particle_mass)) + " kg at this particle mass)");
  return static_cast<TexelMassUnits>(std::floor(kg / kg_per_texel_unit(particle_mass)));
}

DP_HD inline double kg_of_texel_units(TexelMassUnits units, double kg_per_unit) {
  return static_cast<double>(units) * kg_per_unit;
}

// An exact, order-independent sum of texel masses for the water ledger
// (DESIGN §6), which 64 bits of texel units would overflow beyond 256
// particles: whole liquid mass units plus a remainder below one of them.
struct TexelMassSum {
  std::uint64_t mass_units = 0;   // liquid mass units (sph/mass_units.h)
  std::uint64_t texel_units = 0;  // and texel units, < kTexelUnitsPerMassUnit

  void add(TexelMassUnits m) {
    mass_units += m >> kTexelUnitShift;
    texel_units += m & (kTexelUnitsPerMassUnit - 1);
    mass_units += texel_units >> kTexelUnitShift;
    texel_units &= kTexelUnitsPerMassUnit - 1;
  }
  double kg(double kg_per_unit) const {
    return (static_cast<double>(mass_units) * static_cast<double>(kTexelUnitsPerMassUnit) + static_cast<double>(texel_units)) *
           kg_per_unit;
  }
  bool operator==(const TexelMassSum& o) const { return mass_units == o.mass_units && texel_units == o.texel_units; }
};

}  // namespace dp
