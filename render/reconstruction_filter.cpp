#include "reconstruction_filter.h"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dp::render {

ReconstructionFilter::ReconstructionFilter(const dp::io::FilterSettings& s)
    : type_(s.type), radius_(static_cast<float>(s.radius_px)), sigma_(static_cast<float>(s.sigma_px)) {
  if (type_ != dp::io::FilterType::Gaussian) return;
  erf_radius_ = std::erf(radius_ / (sigma_ * std::numbers::sqrt2_v<float>));
  constexpr int kCells = 4096;
  inverse_cdf_.resize(kCells + 1);
  for (int i = 0; i <= kCells; ++i) {
    // The truncated normal's inverse CDF; Boost supplies erf^-1, which the
    // standard library lacks.
    const double p = std::clamp((2.0 * i / kCells - 1.0) * erf_radius_, -0.999999999, 0.999999999);
    inverse_cdf_[static_cast<std::size_t>(i)] =
        std::clamp(static_cast<float>(sigma_ * std::numbers::sqrt2 * boost::math::erf_inv(p)), -radius_, radius_);
  }
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
      const float x = u * static_cast<float>(inverse_cdf_.size() - 1);
      const std::size_t i = std::min(static_cast<std::size_t>(x), inverse_cdf_.size() - 2);
      const float t = x - static_cast<float>(i);
      return (1 - t) * inverse_cdf_[i] + t * inverse_cdf_[i + 1];
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
