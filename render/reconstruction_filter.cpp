#include "reconstruction_filter.h"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dp::render {

ReconstructionFilter::ReconstructionFilter(const dp::io::FilterSettings& s)
    : type_(s.type), radius_(static_cast<float>(s.radius_px)), sigma_(static_cast<float>(s.sigma_px)) {
  if (type_ == dp::io::FilterType::Gaussian) erf_radius_ = std::erf(radius_ / (sigma_ * std::numbers::sqrt2_v<float>));
}

float ReconstructionFilter::sample_axis(float u) const {
  switch (type_) {
    case dp::io::FilterType::Box: return radius_ * (2 * u - 1);
    case dp::io::FilterType::Tent: {
      // Inverse of the tent's cumulative distribution, one half at a time.
      if (u < 0.5f) return radius_ * (std::sqrt(2 * u) - 1);
      return radius_ * (1 - std::sqrt(2 - 2 * u));
    }
    case dp::io::FilterType::Gaussian: {
      // The truncated normal's inverse CDF; Boost supplies erf^-1, which
      // the standard library lacks (in double: its default long double is
      // several times slower and more precise than a pixel offset needs).
      const double p = std::clamp((2.0 * u - 1.0) * erf_radius_, -0.999999999, 0.999999999);
      using namespace boost::math::policies;
      return static_cast<float>(sigma_ * std::numbers::sqrt2 * boost::math::erf_inv(p, make_policy(promote_double<false>())));
    }
  }
  return 0;
}

float ReconstructionFilter::axis_density(float x) const {
  if (std::abs(x) > radius_) return 0;
  switch (type_) {
    case dp::io::FilterType::Box: return 1 / (2 * radius_);
    case dp::io::FilterType::Tent: return (radius_ - std::abs(x)) / (radius_ * radius_);
    case dp::io::FilterType::Gaussian:
      return std::exp(-x * x / (2 * sigma_ * sigma_)) / (sigma_ * std::sqrt(2 * std::numbers::pi_v<float>) * erf_radius_);
  }
  return 0;
}

}  // namespace dp::render
