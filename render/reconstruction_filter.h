#pragma once
// The pixel reconstruction filter, applied by filter importance sampling
// (Ernst et al. 2006; pbrt-v4 Sec. 8.8): each camera sample's offset from
// the pixel centre is drawn with the filter's own (normalised) density, and
// the pixel is the plain mean of its samples. For these non-negative,
// separable filters the density is exact, so every sample weighs 1 and a
// pixel depends on its own samples only (no splatting to neighbours, which
// keeps tiles independent and the image thread-count-invariant).
#include <vector>

#include "render_settings.h"
#include "sampling.h"

namespace dp::render {

class ReconstructionFilter {
 public:
  explicit ReconstructionFilter(const dp::io::FilterSettings& settings);

  // Offset in pixels from the pixel centre, in [-radius, radius]².
  Sample2 sample_offset(Sample2 u) const { return {sample_axis(u.u1), sample_axis(u.u2)}; }
  // The filter's normalised 1D density along one axis.
  float axis_density(float offset) const;
  float radius() const { return radius_; }

 private:
  float sample_axis(float u) const;

  dp::io::FilterType type_;
  float radius_, sigma_;
  float erf_radius_ = 0;  // Gaussian: erf(radius / (sigma sqrt 2))
  // Gaussian: its inverse CDF at u = i / (size - 1), computed once, read
  // with linear interpolation (an exact erf^-1 per sample costs more than a
  // shadow ray; the table's 4096 cells are far below a pixel's resolution).
  std::vector<float> inverse_cdf_;
};

}  // namespace dp::render
