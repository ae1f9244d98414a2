// The dielectric's Fresnel reflectance against closed forms: normal
// incidence ((n-1)/(n+1))^2, and at Brewster's angle, where p-polarised
// light is not reflected at all and s-polarised light reflects
// ((n^2-1)/(n^2+1))^2.
#include <gtest/gtest.h>

#include <cmath>

#include "fresnel.h"
#include "dielectric_bsdf.h"

namespace dp::render {
namespace {

TEST(render_fresnel, NormalIncidenceMatchesClosedForm) {
  for (float n : {1.33f, 1.5f, 2.4f}) {
    const float expected = std::pow((n - 1) / (n + 1), 2.0f);
    EXPECT_NEAR(fresnel_dielectric(1, n).unpolarized(), expected, 1e-6f) << "entering, n = " << n;
    EXPECT_NEAR(fresnel_dielectric(1, 1 / n).unpolarized(), expected, 1e-6f) << "leaving, n = " << n;
  }
}

TEST(render_fresnel, BrewsterAngleAverageMatchesClosedForm) {
  for (float n : {1.33f, 1.5f}) {
    const float cos_brewster = static_cast<float>(std::cos(std::atan(static_cast<double>(n))));
    const FresnelReflectance r = fresnel_dielectric(cos_brewster, n);
    const float s_expected = std::pow((n * n - 1) / (n * n + 1), 2.0f);
    EXPECT_NEAR(r.p, 0.0f, 1e-6f) << "n = " << n;
    EXPECT_NEAR(r.s, s_expected, 1e-5f) << "n = " << n;
    EXPECT_NEAR(r.unpolarized(), 0.5f * s_expected, 1e-5f) << "n = " << n;
  }
}

TEST(render_fresnel, BeyondTheCriticalAngleEverythingReflects) {
  const float n = 1.33f;
  const float cos_critical = std::sqrt(1 - 1 / (n * n));
  EXPECT_EQ(fresnel_dielectric(0.99f * cos_critical, 1 / n).unpolarized(), 1.0f);
  EXPECT_LT(fresnel_dielectric(1.01f * cos_critical, 1 / n).unpolarized(), 1.0f);
  EXPECT_FALSE(refracted_cosine(0.99f * cos_critical, 1 / n).has_value());
}

TEST(render_fresnel, DielectricChoosesReflectionWithFresnelProbability) {
  const float n = 1.5f;
  const float r = std::pow((n - 1) / (n + 1), 2.0f);
  const DielectricBsdf glass(n, 0);
  const Vec3 wo{0, 0, 1};

  auto reflected = glass.sample(wo, 0.999f * r, {});
  ASSERT_TRUE(reflected);
  EXPECT_NEAR(reflected->wi.z, 1.0f, 1e-6f);
  EXPECT_NEAR(reflected->pdf, r, 1e-6f);
  EXPECT_FLOAT_EQ(reflected->weight.g, 1.0f);

  auto refracted = glass.sample(wo, 1.001f * r, {});
  ASSERT_TRUE(refracted);
  EXPECT_NEAR(refracted->wi.z, -1.0f, 1e-6f);
  EXPECT_NEAR(refracted->pdf, 1 - r, 1e-6f);
  EXPECT_NEAR(refracted->weight.g, 1 / (n * n), 1e-6f);  // radiance narrows into the denser medium
}

TEST(render_fresnel, RefractionObeysSnellsLaw) {
  const float n = 1.33f;
  const DielectricBsdf water(n, 0);
  const float sin_incident = 0.6f;
  const Vec3 wo{sin_incident, 0, 0.8f};
  auto refracted = water.sample(wo, 0.999f, {});  // R at 37 degrees is far below 0.999
  ASSERT_TRUE(refracted);
  EXPECT_LT(refracted->wi.z, 0);
  EXPECT_NEAR(-refracted->wi.x, sin_incident / n, 1e-6f);  // continues on the far side of the normal
  EXPECT_NEAR(length(refracted->wi), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace dp::render
