#pragma once
// Piecewise-constant densities over [0,1) and [0,1)², sampled by inverting
// their cumulative sums (pbrt-v4 Sec. A.4-A.5). They importance-sample
// environment maps and pick emissive triangles by power.
#include <cstddef>
#include <vector>

#include "sampling.h"

namespace dp::render {

class PiecewiseConstant1D {
 public:
  // Non-negative weights of equal-width cells; all zero gives a uniform density.
  explicit PiecewiseConstant1D(std::vector<float> weights);

  std::size_t size() const { return weights_.size(); }
  double integral() const { return integral_; }  // mean weight over [0,1)

  struct Continuous {
    float x;           // in [0, 1)
    float pdf;         // density at x
    std::size_t cell;  // the cell x lies in
  };
  Continuous sample_continuous(float u) const;
  // A cell drawn with probability weight / sum of weights.
  std::size_t sample_discrete(float u, float* probability) const;
  float discrete_probability(std::size_t cell) const;
  float pdf(float x) const;

 private:
  std::size_t find_cell(float u) const;

  std::vector<float> weights_;
  std::vector<double> cdf_;  // size()+1 entries, 0 ... 1
  double integral_ = 0;
};

class PiecewiseConstant2D {
 public:
  // weights[row * width + col]; rows run along v, columns along u.
  PiecewiseConstant2D(const std::vector<float>& weights, std::size_t width, std::size_t height);

  struct Sample {
    float u, v;
    float pdf;
  };
  Sample sample(Sample2 u) const;
  float pdf(float u, float v) const;

 private:
  std::vector<PiecewiseConstant1D> rows_;  // conditional density of u given the row
  PiecewiseConstant1D marginal_;           // density of rows
};

}  // namespace dp::render
