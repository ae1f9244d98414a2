#pragma once
// The emissive triangles of a scene (meshes whose material has emission):
// each emits its material's radiance from its front (outward) side. A light
// sample picks a triangle with probability proportional to its power
// (area x luminance), then a point uniformly on it (pbrt-v4 Sec. 12.2,
// 6.5.1).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "piecewise_constant.h"
#include "rgb.h"
#include "sampling.h"
#include "vec3.h"

namespace dp::render {

struct AreaLightSample {
  Vec3 position;
  Vec3 normal;  // unit, the emitting side
  Rgb radiance;
  float pdf_area = 0;  // per unit area, the triangle's choice included
};

class AreaLights {
 public:
  // Adds every triangle of one geometry (Embree ID `geometry`), whose
  // outward normals are `normals` (one per triangle).
  void add(unsigned geometry, const std::vector<std::array<Vec3, 3>>& triangles, const std::vector<Vec3>& normals, Rgb emission);
  void finish();  // after the last add

  bool empty() const { return triangles_.empty(); }
  std::size_t count() const { return triangles_.size(); }
  AreaLightSample sample(float u_pick, Sample2 u) const;
  // Density per unit area with which sample() returns a point on this triangle.
  float pdf_area(unsigned geometry, unsigned primitive) const;

 private:
  struct Triangle {
    Vec3 a, b, c, normal;
    float area;
    Rgb emission;
  };
  std::vector<Triangle> triangles_;
  std::vector<std::int64_t> first_of_geometry_;  // index into triangles_, -1 for non-emitters
  std::unique_ptr<PiecewiseConstant1D> power_;
};

}  // namespace dp::render
