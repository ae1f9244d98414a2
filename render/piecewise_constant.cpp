#include "piecewise_constant.h"

#include <algorithm>
#include <stdexcept>

namespace dp::render {

PiecewiseConstant1D::PiecewiseConstant1D(std::vector<float> weights) : weights_(std::move(weights)) {
  if (weights_.empty()) throw std::invalid_argument("piecewise-constant density over no cells");
  double total = 0;
  for (float w : weights_) total += std::max(0.0f, w);
  if (!(total > 0)) std::fill(weights_.begin(), weights_.end(), 1.0f), total = static_cast<double>(weights_.size());
  const double n = static_cast<double>(weights_.size());
  integral_ = total / n;
  cdf_.resize(weights_.size() + 1);
  cdf_[0] = 0;
  double running = 0;
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    running += std::max(0.0f, weights_[i]);
    cdf_[i + 1] = running / total;
  }
  cdf_.back() = 1;
}

std::size_t PiecewiseConstant1D::find_cell(float u) const {
  // The last cell whose cumulative start is <= u; empty cells are never found.
  const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
  std::size_t cell = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - cdf_.begin() - 1));
  cell = std::min(cell, weights_.size() - 1);
  while (cell + 1 < weights_.size() && cdf_[cell + 1] == cdf_[cell]) ++cell;
  return cell;
}

PiecewiseConstant1D::Continuous PiecewiseConstant1D::sample_continuous(float u) const {
  const std::size_t cell = find_cell(u);
  const double width = cdf_[cell + 1] - cdf_[cell];
  const double offset = width > 0 ? (u - cdf_[cell]) / width : 0.5;
  const double n = static_cast<double>(weights_.size());
  float x = static_cast<float>((static_cast<double>(cell) + std::clamp(offset, 0.0, 1.0)) / n);
  x = std::min(x, std::nextafter(1.0f, 0.0f));
  return {x, static_cast<float>(std::max(0.0f, weights_[cell]) / integral_), cell};
}

std::size_t PiecewiseConstant1D::sample_discrete(float u, float* probability) const {
  const std::size_t cell = find_cell(u);
  if (probability) *probability = discrete_probability(cell);
  return cell;
}

float PiecewiseConstant1D::discrete_probability(std::size_t cell) const {
  return static_cast<float>(cdf_[cell + 1] - cdf_[cell]);
}

float PiecewiseConstant1D::pdf(float x) const {
  const auto n = weights_.size();
  const std::size_t cell = std::min(n - 1, static_cast<std::size_t>(std::max(0.0f, x) * static_cast<float>(n)));
  return static_cast<float>(std::max(0.0f, weights_[cell]) / integral_);
}

namespace {
std::vector<PiecewiseConstant1D> row_densities(const std::vector<float>& weights, std::size_t width, std::size_t height) {
  if (weights.size() != width * height) throw std::invalid_argument("piecewise-constant 2D density: weights do not fill the grid");
  std::vector<PiecewiseConstant1D> rows;
  rows.reserve(height);
  for (std::size_t r = 0; r < height; ++r)
    rows.emplace_back(std::vector<float>(weights.begin() + static_cast<std::ptrdiff_t>(r * width),
                                         weights.begin() + static_cast<std::ptrdiff_t>((r + 1) * width)));
  return rows;
}
std::vector<float> row_integrals(const std::vector<float>& weights, std::size_t width, std::size_t height) {
  std::vector<float> sums(height);
  for (std::size_t r = 0; r < height; ++r) {
    double s = 0;
    for (std::size_t c = 0; c < width; ++c) s += std::max(0.0f, weights[r * width + c]);
    sums[r] = static_cast<float>(s / static_cast<double>(width));
  }
  return sums;
}
}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<float>& weights, std::size_t width, std::size_t height)
    : rows_(row_densities(weights, width, height)), marginal_(row_integrals(weights, width, height)) {}

PiecewiseConstant2D::Sample PiecewiseConstant2D::sample(Sample2 u) const {
  const auto row = marginal_.sample_continuous(u.u2);
  const auto col = rows_[row.cell].sample_continuous(u.u1);
  return {col.x, row.x, row.pdf * col.pdf};
}

float PiecewiseConstant2D::pdf(float u, float v) const {
  const std::size_t h = rows_.size();
  const std::size_t row = std::min(h - 1, static_cast<std::size_t>(std::max(0.0f, v) * static_cast<float>(h)));
  return marginal_.pdf(v) * rows_[row].pdf(u);
}

}  // namespace dp::render
