#pragma once
// The coupling's settings (paper Sec. 5-6) as plain numbers; the scene's
// `simulation.coupling` section (docs/scene-format.md) is read into this.
#include "coupling/evaporation_rate_smith1994.h"
#include "coupling/heat_grid_particles.h"

namespace dp {

struct CouplingSettings {
  EvaporationCoefficients coefficients;  // a, b of Eq. 12, physical (Smith et al. 1994 by default)
  // Runs evaporation and condensation this many times faster than Eq. 12
  // with `coefficients` would, for shots whose phase change must show within
  // seconds of simulated time (art direction, not physics: the scenes'
  // reasons in docs/paper-map.md, departures). 1 is the physical rate.
  double phase_change_time_scale = 1.0;
  EvaporationCoefficients rate_coefficients() const {
    return EvaporationCoefficients{coefficients.a * phase_change_time_scale, coefficients.b * phase_change_time_scale};
  }
  AirHeatProperties air;                 // rho_c, C_c, kappa_c of Eq. 15
  bool heat_exchange = true;             // Alg. 1 line 13
  bool particle_evaporation = true;      // line 15
  bool texel_exchange = true;            // line 16
  bool particle_emission = true;         // line 17: texels -> particles
  // Beyond the paper: evaporation cools the liquid by L dm / (m C); off
  // reproduces the paper. Texels are not cooled: their temperature comes
  // from the rigid particles every step (Eq. 7).
  bool latent_heat = false;
  float latent_heat_j_kg = 2.26e6f;
  // Alg. 1 line 19, our definition (coupling/path_force.h): liquid is drawn
  // along a surface towards its wetter texels (Akinci 2013's adhesion
  // kernel weighted by the difference in wetting history), so later drops
  // follow earlier paths. Off, or a uniformly wet surface, leaves the step
  // as the paper's.
  bool path_force = false;
  float path_adhesion = 10.0f;  // beta_path, the units of the rigids' adhesion beta
  // Texels with a wetting history at or above this do not condense (Sec. 6.2).
  float wet_threshold = 0.36787944f;
};

}  // namespace dp
