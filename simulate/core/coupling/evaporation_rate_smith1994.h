#pragma once
// The rate of evaporation and condensation of a surface element (paper
// Sec. 3.4 and 6.1): Smith, Löf & Jones 1994's empirical law (paper Eq. 12)
//   dm_s/dtau = A_s (a + b |v|) (p_sat(T_s) - p_c)
// with p_sat by Magnus (Eq. 11) and p_c by the ideal gas (Eq. 10), both in
// air/vapor_pressure.h, split by its sign into evaporation (Eq. 16) and
// condensation (Eq. 17, without the velocity term: b = 0).
#include <cmath>

#include "air/vapor_pressure.h"
#include "backend/host_device.h"

namespace dp {

// a in kg/(m^2 s Pa), b in kg/(m^3 Pa) (per m/s of air speed). The paper
// gives no values. Defaults: Smith, Löf & Jones 1994's law for an
// unoccupied outdoor pool in its metric form,
//   q = (30.6 + 32.1 v)(p_w - p_a)  kJ/(h m^2), p in mmHg, v in m/s,
// i.e. 72 % of the ASHRAE (Carrier) still-air coefficient, 95 Btu/(h ft^2
// inHg) = 42.5 kJ/(h m^2 mmHg), which is what their measurements gave at
// near-zero wind. In SI: 30.6 kJ/(h m^2 mmHg) = 30.6e3 / 3600 / 133.322
// W/(m^2 Pa) = 63.8 W/(m^2 kPa) (not 30.6: the coefficients are not per
// kPa), turned into mass by the latent heat near 20 degC, L = 2.45 MJ/kg.
// Sources: docs/paper-map.md (departures).
inline constexpr double kSmithHeatCoefficientA = 30.6;   // kJ/(h m^2 mmHg)
inline constexpr double kSmithHeatCoefficientB = 32.1;   // kJ/(h m^2 mmHg) per m/s
inline constexpr double kPascalPerMmHg = 133.322387415;
inline constexpr double kSmithLatentHeat = 2.45e6;       // J/kg
DP_HD constexpr double smith_coefficient_si(double kj_per_h_m2_mmhg) {
  return kj_per_h_m2_mmhg * 1e3 / 3600.0 / kPascalPerMmHg / kSmithLatentHeat;  // kg/(m^2 s Pa)
}

struct EvaporationCoefficients {
  double a = smith_coefficient_si(kSmithHeatCoefficientA);  // 2.602e-8 kg/(m^2 s Pa)
  double b = smith_coefficient_si(kSmithHeatCoefficientB);  // 2.730e-8 kg/(m^3 Pa)
};

// What a surfel sees of the air at its position: vapor density (kg/m^3),
// temperature (K) and speed (m/s), interpolated from the cells.
struct AirAtSurfel {
  double vapor_density;
  double temperature;
  double speed;
};

// Eq. 12 in kg/s from the two pressures (Pa); positive: the surfel loses
// mass (evaporation). Kernels that need both signs compute p_sat and p_c
// once and call this.
DP_HD inline double smith_mass_rate_at(double area, double a, double b, double speed, double p_sat, double p_c) {
  return area * (a + b * speed) * (p_sat - p_c);
}

// Eq. 12 in kg/s; positive: the surfel loses mass (evaporation).
DP_HD inline double smith_mass_rate(double area, double a, double b, double speed, double surface_kelvin, const AirAtSurfel& air) {
  const double p_sat = saturation_pressure_at_kelvin(surface_kelvin);          // Eq. 11
  const double p_c = vapor_pressure(air.vapor_density, air.temperature);        // Eq. 10
  return smith_mass_rate_at(area, a, b, speed, p_sat, p_c);
}

// max(x, 0), NaN -> 0. As a compare: fmax and fmin are library calls on
// x86-64 (they order signed zeros), and a call in a per-texel kernel makes
// the compiler spill every vector register around it. Only the sign of a
// zero rate differs from fmax's, and a zero rate moves nothing either way.
DP_HD inline double positive_part(double x) { return x > 0.0 ? x : 0.0; }

// Eq. 16: evaRate(c, s) = max(dm_s/dtau, 0), kg/s.
DP_HD inline double evaporation_rate(double area, const EvaporationCoefficients& k, double surface_kelvin, const AirAtSurfel& air) {
  return positive_part(smith_mass_rate(area, k.a, k.b, air.speed, surface_kelvin, air));
}
DP_HD inline double evaporation_rate_at(double area, const EvaporationCoefficients& k, double speed, double p_sat, double p_c) {
  return positive_part(smith_mass_rate_at(area, k.a, k.b, speed, p_sat, p_c));
}

// Eq. 17: condRate(c, s) = -min(dm_s/dtau, 0) = max(-dm_s/dtau, 0) with b = 0, kg/s.
DP_HD inline double condensation_rate(double area, const EvaporationCoefficients& k, double surface_kelvin, const AirAtSurfel& air) {
  return positive_part(-smith_mass_rate(area, k.a, 0.0, air.speed, surface_kelvin, air));
}
DP_HD inline double condensation_rate_at(double area, const EvaporationCoefficients& k, double p_sat, double p_c) {
  return positive_part(-smith_mass_rate_at(area, k.a, 0.0, 0.0, p_sat, p_c));
}

}  // namespace dp
