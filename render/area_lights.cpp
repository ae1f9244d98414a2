#include "area_lights.h"

#include <cmath>
#include <stdexcept>

namespace dp::render {

void AreaLights::add(unsigned geometry, const std::vector<std::array<Vec3, 3>>& triangles, const std::vector<Vec3>& normals,
                     Rgb emission) {
  if (first_of_geometry_.size() <= geometry) first_of_geometry_.resize(geometry + 1, -1);
  first_of_geometry_[geometry] = static_cast<std::int64_t>(triangles_.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    const float area = 0.5f * length(cross(t[1] - t[0], t[2] - t[0]));
    triangles_.push_back({t[0], t[1], t[2], normals[i], area, emission});
  }
}

void AreaLights::finish() {
  if (triangles_.empty()) return;
  std::vector<float> power(triangles_.size());
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const Rgb& e = triangles_[i].emission;
    power[i] = triangles_[i].area * (0.2126f * e.r + 0.7152f * e.g + 0.0722f * e.b);
  }
  power_ = std::make_unique<PiecewiseConstant1D>(std::move(power));
}

AreaLightSample AreaLights::sample(float u_pick, Sample2 u) const {
  float probability = 0;
  const Triangle& t = triangles_[power_->sample_discrete(u_pick, &probability)];
  // Uniform on the triangle: fold the unit square onto the lower-left half.
  float b1 = u.u1, b2 = u.u2;
  if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
  const Vec3 p = t.a + b1 * (t.b - t.a) + b2 * (t.c - t.a);
  return {p, t.normal, t.emission, t.area > 0 ? probability / t.area : 0.0f};
}

float AreaLights::pdf_area(unsigned geometry, unsigned primitive) const {
  if (geometry >= first_of_geometry_.size() || first_of_geometry_[geometry] < 0) return 0;
  const std::size_t i = static_cast<std::size_t>(first_of_geometry_[geometry]) + primitive;
  return triangles_[i].area > 0 ? power_->discrete_probability(i) / triangles_[i].area : 0.0f;
}

}  // namespace dp::render
