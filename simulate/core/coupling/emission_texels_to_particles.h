#pragma once
// Particle condensation, texels -> particles (paper Sec. 6.2 "Evaporation
// and condensation of particles", Alg. 1 line 17): where the texels that
// feed a seeding point (surface/seeding_points.h, Poisson-disk, Bridson
// 2007) hold at least one full particle's mass together, a liquid particle
// is emitted at the seed and its mass taken from those texels. No balance
// is needed: only mass that is there is taken. Seeds whose texels were
// touched by liquid recently (wetting history, Sec. 4.3) emit nothing, so
// particles do not appear where particles already are.
// The particle appears one spacing off the surface along the seed's normal,
// at rest, at its texels' mass-weighted temperature.
//
// Each texel feeds at most one seed, so a seed's kernel may write its own
// texels' masses: still one writer per element.
#include <cstdint>

#include "backend/host_device.h"
#include "coupling/exact_units.h"
#include "math/vec3.h"
#include "sph/mass_units.h"

namespace dp {

// One full particle in texel units: 2^24 mass units of 2^32 texel units.
inline constexpr TexelMassUnits kParticleTexelUnits = static_cast<TexelMassUnits>(kFullParticleUnits) << kTexelUnitShift;

struct EmitFromSeeds {
  const std::uint32_t* texel_offset;  // seed s feeds texel_index[texel_offset[s], texel_offset[s + 1])
  const std::uint32_t* texel_index;
  const float* wetting;
  const float* texel_temperature;
  float wet_threshold;
  TexelMassUnits* mass;
  std::uint8_t* emitted;     // per seed: 1 when it emits this step
  float* temperature;        // per seed: the emitted particle's temperature (K)

  DP_HD void operator()(std::size_t s) const {
    emitted[s] = 0;
    const std::uint32_t b = texel_offset[s], e = texel_offset[s + 1];
    TexelMassUnits total = 0;
    bool wet = false;
    for (std::uint32_t q = b; q < e; ++q) {
      const std::uint32_t t = texel_index[q];
      const TexelMassUnits m = mass[t];
      total = total > ~m ? ~TexelMassUnits{0} : total + m;  // saturating: a total above 2^64 is enough anyway
      wet = wet || wetting[t] >= wet_threshold;
    }
    if (wet || total < kParticleTexelUnits) return;
    // Take the particle in proportion to each texel's mass, rounded down,
    // then the few units still missing (fewer than the seed's texels) from
    // the texels in order: exactly kParticleTexelUnits, none below zero
    // (what is left, total - sum of floors, is at least what is missing).
    TexelMassUnits taken = 0;
    double t_sum = 0, w_sum = 0;
    for (std::uint32_t q = b; q < e; ++q) {
      const std::uint32_t t = texel_index[q];
      const TexelMassUnits share = scale_units(mass[t], kParticleTexelUnits, total);
      t_sum += static_cast<double>(mass[t]) * texel_temperature[t];
      w_sum += static_cast<double>(mass[t]);
      mass[t] -= share;
      taken += share;
    }
    for (std::uint32_t q = b; q < e && taken < kParticleTexelUnits; ++q) {
      const std::uint32_t t = texel_index[q];
      const TexelMassUnits missing = kParticleTexelUnits - taken, d = mass[t] < missing ? mass[t] : missing;
      mass[t] -= d;
      taken += d;
    }
    temperature[s] = static_cast<float>(t_sum / w_sum);
    emitted[s] = 1;
  }
};

struct IsSet {
  const std::uint8_t* flag;
  DP_HD bool operator()(std::size_t i) const { return flag[i] != 0; }
};

}  // namespace dp
