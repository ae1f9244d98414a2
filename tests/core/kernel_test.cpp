// The cubic spline kernel against its analytic properties: unit integral
// over its support, gradient equal to the derivative of W, compact support.
#include <gtest/gtest.h>

#include "sph/kernel_cubic_spline.h"

namespace dp {
namespace {

TEST(CubicSplineKernel, IntegratesToOneOverItsSupport) {
  const float h = 0.04f;
  CubicSplineKernel k = CubicSplineKernel::with_support(h);
  // Radial quadrature: integral of 4 pi r^2 W(r) dr, midpoint rule.
  const int n = 20000;
  double integral = 0;
  for (int i = 0; i < n; ++i) {
    double r = (i + 0.5) * h / n;
    integral += 4.0 * 3.14159265358979 * r * r * k.W(static_cast<float>(r)) * (h / n);
  }
  EXPECT_NEAR(integral, 1.0, 1e-5);
}

TEST(CubicSplineKernel, GradientIsTheDerivativeOfW) {
  CubicSplineKernel k = CubicSplineKernel::with_support(1.0f);
  for (float r : {0.1f, 0.3f, 0.5f, 0.7f, 0.95f}) {
    Vec3 d{r * 0.6f, r * 0.8f, 0.0f};
    Vec3 g = k.gradW(d);
    const float eps = 1e-3f;
    float dWdr = (k.W(r + eps) - k.W(r - eps)) / (2 * eps);
    EXPECT_NEAR(g.x, dWdr * 0.6f, 2e-3f * k.sigma) << "r=" << r;
    EXPECT_NEAR(g.y, dWdr * 0.8f, 2e-3f * k.sigma) << "r=" << r;
  }
  EXPECT_EQ(k.W(1.0f), 0.0f);
  EXPECT_EQ(length(k.gradW(Vec3{1.0f, 0, 0})), 0.0f);
  EXPECT_EQ(k.gradient_factor(Vec3{}), 0.0f);  // coincident particles: no direction, no force (not 0/0)
}

}  // namespace
}  // namespace dp
