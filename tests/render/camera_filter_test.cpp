// Camera and reconstruction filter against their definitions. A thin lens
// focused at distance d brings every ray through one film point to the same
// point on the plane d ahead (the thin-lens law as pbrt-v4 Sec. 5.2.3 uses
// it), from origins spread over the aperture disk; a pinhole is the lens of
// radius 0. Filter importance sampling must draw offsets with the filter's
// own density: the box's variance is r²/3, the tent's r²/6, and the
// truncated Gaussian's sigma² (1 - 2 r phi(r/sigma) / (sigma erf(r/(sigma sqrt 2)))),
// phi the standard normal density.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "perspective_camera.h"
#include "random_stream.h"
#include "reconstruction_filter.h"

namespace dp::render {
namespace {

dp::io::CameraSettings thin_lens(double aperture, double focus) {
  dp::io::CameraSettings c;
  c.model = dp::io::CameraModel::ThinLens;
  c.position_m = {0.2, 0.5, 2};
  c.look_at_m = {0, 0, 0};
  c.aperture_radius_m = aperture;
  c.focus_distance_m = focus;
  return c;
}

TEST(render_camera, ThinLensRaysMeetOnThePlaneInFocus) {
  const PerspectiveCamera camera(thin_lens(0.05, 1.5), 64, 48);
  const PerspectiveCamera pinhole(thin_lens(0, 1.5), 64, 48);
  const Vec3 axis = camera.forward();
  for (auto [x, y] : {std::pair{32.0f, 24.0f}, {3.5f, 40.25f}, {60.0f, 1.0f}}) {
    const Ray centre = pinhole.ray_through(x, y);
    const Vec3 focus = centre.origin + (1.5f / dot(centre.direction, axis)) * centre.direction;
    double spread = 0;
    for (std::uint32_t i = 0; i < 200; ++i) {
      RandomStream random(4, 0, 0, i);
      const Ray r = camera.ray_through(x, y, {random.uniform(), random.uniform()});
      // Origin on the aperture disk, in the lens plane.
      const Vec3 offset = r.origin - camera.position();
      EXPECT_LE(length(offset), 0.05f * (1 + 1e-5f));
      EXPECT_NEAR(dot(offset, axis), 0.0f, 1e-6f);
      spread = std::max(spread, static_cast<double>(length(offset)));
      // Through the in-focus point.
      const float t = dot(focus - r.origin, axis) / dot(r.direction, axis);
      EXPECT_LT(length(r.origin + t * r.direction - focus), 1e-5f);
    }
    EXPECT_GT(spread, 0.04);  // the aperture is used, not just its centre
  }
}

TEST(render_camera, ConcentricDiskMapIsUniformInArea) {
  // Fraction of samples within radius 1/2 must be 1/4.
  int inside = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    RandomStream random(5, 0, 0, static_cast<std::uint32_t>(i));
    const Sample2 d = sample_concentric_disk({random.uniform(), random.uniform()});
    ASSERT_LE(d.u1 * d.u1 + d.u2 * d.u2, 1.0f + 1e-6f);
    inside += d.u1 * d.u1 + d.u2 * d.u2 < 0.25f;
  }
  EXPECT_NEAR(static_cast<double>(inside) / n, 0.25, 0.005);
}

double sampled_variance(const ReconstructionFilter& filter, float* largest) {
  double sum2 = 0;
  const int n = 200000;
  *largest = 0;
  for (int i = 0; i < n; ++i) {
    RandomStream random(6, 0, 0, static_cast<std::uint32_t>(i));
    const Sample2 o = filter.sample_offset({random.uniform(), random.uniform()});
    sum2 += o.u1 * o.u1;
    *largest = std::max({*largest, std::abs(o.u1), std::abs(o.u2)});
  }
  return sum2 / n;
}

TEST(render_filter, OffsetsFollowTheFilterDensity) {
  float largest = 0;
  dp::io::FilterSettings box{dp::io::FilterType::Box, 0.5, 0};
  EXPECT_NEAR(sampled_variance(ReconstructionFilter(box), &largest), 0.25 / 3, 0.002);
  EXPECT_LE(largest, 0.5f);
  dp::io::FilterSettings tent{dp::io::FilterType::Tent, 1, 0};
  EXPECT_NEAR(sampled_variance(ReconstructionFilter(tent), &largest), 1.0 / 6, 0.003);
  EXPECT_LE(largest, 1.0f);
  dp::io::FilterSettings gaussian{dp::io::FilterType::Gaussian, 1.5, 0.5};
  const double r = 1.5, sigma = 0.5;
  const double phi = std::exp(-0.5 * (r / sigma) * (r / sigma)) / std::sqrt(2 * std::numbers::pi);
  const double expected = sigma * sigma * (1 - 2 * (r / sigma) * phi / std::erf(r / (sigma * std::numbers::sqrt2)));
  EXPECT_NEAR(sampled_variance(ReconstructionFilter(gaussian), &largest), expected, 0.003);
  EXPECT_LE(largest, 1.5f);
  // The density it reports integrates to one.
  const ReconstructionFilter g(gaussian);
  double integral = 0;
  for (int i = 0; i < 3000; ++i) integral += g.axis_density(-1.5f + 3.0f * (static_cast<float>(i) + 0.5f) / 3000) * (3.0 / 3000);
  EXPECT_NEAR(integral, 1.0, 1e-3);
}

}  // namespace
}  // namespace dp::render
