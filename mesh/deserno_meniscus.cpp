#include "deserno_meniscus.h"

#include <cmath>
#include <stdexcept>

namespace dp::mesh {

DesernoMeniscus2004::DesernoMeniscus2004(double psi0, double capillary_length)
    : psi0_(psi0),
      l_(capillary_length),
      cos_half_(std::cos(psi0 / 2)),
      sin_half_(std::sin(psi0 / 2)),
      cos_(std::cos(psi0)) {
  if (!(std::abs(psi0) < M_PI / 2)) throw std::invalid_argument("Deserno meniscus: |psi0| must be below 90 degrees");
  if (!(capillary_length > 0)) throw std::invalid_argument("Deserno meniscus: capillary length must be positive");
}

double DesernoMeniscus2004::x(double s) const {
  const double t = s / l_, c = std::cosh(t), sh = std::sinh(t);
  return l_ * (t * c + (t * cos_half_ - (1 - cos_)) * sh) / (c + cos_half_ * sh);
}

double DesernoMeniscus2004::y(double s) const {
  const double t = s / l_;
  return l_ * 2 * sin_half_ / (std::cosh(t) + cos_half_ * std::sinh(t));
}

double DesernoMeniscus2004::height_at_distance(double distance) const {
  if (!(distance > 0)) return y(0);
  // Far from the wall the meniscus has decayed (y ~ e^(-s/l)); cosh would
  // overflow long before it matters.
  if (distance > 40 * l_) return 0;
  // x(s) >= s cos(psi0) and x(s) <= s, so the root lies in [distance, distance / cos psi0].
  double lo = distance, hi = distance / cos_;
  // Newton from the middle with dx/ds = cos(psi(s)) > 0, safeguarded by bisection.
  double s = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double f = x(s) - distance;
    if (std::abs(f) <= 1e-13 * l_) break;
    if (f > 0) hi = s; else lo = s;
    const double h = 1e-7 * l_;
    const double slope = (x(s + h) - x(s - h)) / (2 * h);
    double next = s - f / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    s = next;
  }
  return y(s);
}

}  // namespace dp::mesh
