#pragma once
// The coupling's settings (paper Sec. 5-6) as plain numbers; the scene's
// `simulation.coupling` section (docs/scene-format.md) is read into this.
#include "coupling/evaporation_rate_smith1994.h"
#include "coupling/heat_grid_particles.h"

namespace dp {

struct CouplingSettings {
  EvaporationCoefficients coefficients;  // a, b of Eq. 12
  AirHeatProperties air;                 // rho_c, C_c, kappa_c of Eq. 15
  bool heat_exchange = true;             // Alg. 1 line 13
  bool particle_evaporation = true;      // line 15
  bool texel_exchange = true;            // line 16
  bool particle_emission = true;         // line 17: texels -> particles
  // Texels with a wetting history at or above this do not condense (Sec. 6.2).
  float wet_threshold = 0.36787944f;
};

}  // namespace dp
