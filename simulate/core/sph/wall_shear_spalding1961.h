#pragma once
// The law of the wall in Spalding's single formula (D. B. Spalding 1961, "A
// single formula for the law of the wall", J. Appl. Mech. 28, 455-458):
//
//   y+ = u+ + e^(-kappa B) [e^(kappa u+) - 1 - kappa u+ - (kappa u+)^2 / 2 - (kappa u+)^3 / 6],
//
// with u+ = u / u_tau, y+ = y u_tau / nu and u_tau = sqrt(tau_w / rho). It
// joins the viscous sublayer (u+ = y+) to the logarithmic layer
// (u+ = ln(y+) / kappa + B) through the buffer layer in one expression, so
// one wall model serves a first particle layer at any distance.
//
// A particle a distance y from the wall, sliding along it at u, feels the
// wall shear tau_w = rho u_tau^2. The wall term of Morris et al. 1997 gives a
// laminar wall shear, rho nu u / y, from the same particle; the law of the
// wall asks for (y+ / u+) times as much (the wall viscosity nu + nu_t of
// finite-volume wall functions, nu_t = nu (y+ / u+ - 1)). Where the liquid is
// resolved down to the sublayer, y+ = u+ and the factor is 1: no-slip.
#include <cmath>

#include "backend/host_device.h"

namespace dp {

// How the liquid's first layer feels a wall in the viscous term: resolved
// no-slip (Morris et al. 1997 as published) or the law of the wall.
enum class WallShear { NoSlip, Spalding1961 };

// Pope, "Turbulent Flows" (2000), Sec. 7.1.4: kappa = 0.41, B = 5.2 for
// smooth walls.
constexpr float kVonKarman = 0.41f;
constexpr float kLogLawIntercept = 5.2f;

// Spalding's y+ for a given u+.
DP_HD inline float spalding_y_plus(float u_plus) {
  const float k = kVonKarman * u_plus;
  return u_plus + expf(-kVonKarman * kLogLawIntercept) * (expf(k) - 1.0f - k - 0.5f * k * k - k * k * k / 6.0f);
}

DP_HD inline float spalding_dy_plus_du_plus(float u_plus) {
  const float k = kVonKarman * u_plus;
  return 1.0f + kVonKarman * expf(-kVonKarman * kLogLawIntercept) * (expf(k) - 1.0f - k - 0.5f * k * k);
}

// The u+ at which a particle at y with speed u sits on Spalding's law:
// u+ y+(u+) = u y / nu (the particle's wall Reynolds number). The left side
// is convex and increasing, so Newton's method started above the root falls
// onto it monotonically. sqrt(Re) lies above it (y+ >= u+); so does 60 for
// any Re below 3e11 (u+ y+ = 3.4e11 there), far beyond a liquid's.
DP_HD inline float spalding_u_plus(float wall_reynolds) {
  if (wall_reynolds <= 0.0f) return 0.0f;
  float u_plus = fminf(sqrtf(wall_reynolds), 60.0f);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const float y_plus = spalding_y_plus(u_plus);
    const float step = (u_plus * y_plus - wall_reynolds) / (y_plus + u_plus * spalding_dy_plus_du_plus(u_plus));
    u_plus -= step;
    if (fabsf(step) <= 1e-6f * u_plus) break;
  }
  return u_plus;
}

// y+ / u+ = (u y / nu) / u+^2: the wall shear of the law of the wall over
// the laminar rho nu u / y. At least 1: a wall is never weaker than no-slip.
DP_HD inline float wall_shear_factor_spalding1961(float speed, float wall_distance, float kinematic_viscosity) {
  const float reynolds = speed * wall_distance / kinematic_viscosity;
  if (reynolds <= 1.0f) return 1.0f;  // inside the sublayer, y+ = u+ < 1
  const float u_plus = spalding_u_plus(reynolds);
  return fmaxf(1.0f, reynolds / (u_plus * u_plus));
}

}  // namespace dp
