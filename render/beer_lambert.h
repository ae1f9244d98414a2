#pragma once
// Fraction of light surviving a straight path through an absorbing medium.
#include <cmath>

#include "rgb.h"

namespace dp::render {

inline Rgb beer_lambert_transmittance(Rgb absorption_per_m, float distance_m) {
  return {std::exp(-absorption_per_m.r * distance_m), std::exp(-absorption_per_m.g * distance_m),
          std::exp(-absorption_per_m.b * distance_m)};
}

}  // namespace dp::render
