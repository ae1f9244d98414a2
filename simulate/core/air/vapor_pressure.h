#pragma once
// Vapor pressure of the air (paper Eq. 10, ideal gas, Rogers & Yau 1996) and
// saturation vapor pressure over water (paper Eq. 11, Magnus' formula with
// the coefficients the paper gives). Used to turn a relative humidity into a
// vapor density; the evaporation model (paper Sec. 6) uses the same two.
#include <cmath>

#include "backend/host_device.h"

namespace dp {

inline constexpr double kWaterVaporGasConstant = 461.5;  // R_w, J/(kg K)
inline constexpr double kCelsiusZero = 273.15;            // K

// Eq. 11: p_sat(T) in Pa, T in degrees Celsius.
DP_HD inline double magnus_saturation_pressure(double celsius) {
  return 611.2 * exp(17.62 * celsius / (243.12 + celsius));
}

// Eq. 11 at a temperature in kelvin: the one place where the simulator's
// kelvin meet the formula's degrees Celsius.
DP_HD inline double saturation_pressure_at_kelvin(double kelvin) { return magnus_saturation_pressure(kelvin - kCelsiusZero); }

// Eq. 10: p = rho_v R_w T, with rho_v = m_c / V_c and T in kelvin.
DP_HD inline double vapor_pressure(double vapor_density, double kelvin) {
  return vapor_density * kWaterVaporGasConstant * kelvin;
}

// Eq. 10 inverted: the vapor density (kg/m^3) at pressure `pascal` in air at `kelvin`.
DP_HD inline double vapor_density_at_pressure(double pascal, double kelvin) { return pascal / (kWaterVaporGasConstant * kelvin); }

// The vapor density (kg/m^3) of air at `kelvin` with relative humidity
// `rh` in [0, 1]: rh p_sat / (R_w T).
DP_HD inline double vapor_density_at_humidity(double rh, double kelvin) {
  return vapor_density_at_pressure(rh * saturation_pressure_at_kelvin(kelvin), kelvin);
}

}  // namespace dp
