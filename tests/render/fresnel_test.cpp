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

// Conductors: at normal incidence R = ((n-1)² + k²) / ((n+1)² + k²)
// (Born & Wolf, Sec. 14.2); with k = 0 the dielectric's equations; at
// grazing incidence every surface reflects everything.
TEST(render_fresnel, ConductorNormalIncidenceMatchesClosedForm) {
  for (auto [n, k] : {std::pair{1.66f, 9.22f}, {0.2f, 3.0f}, {2.5f, 0.5f}}) {
    const float expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    EXPECT_NEAR(fresnel_conductor(1, n, k), expected, 1e-5f) << n << " " << k;
  }
}

TEST(render_fresnel, ConductorWithoutAbsorptionIsADielectric) {
  for (float c : {1.0f, 0.8f, 0.5f, 0.2f, 0.05f})
    EXPECT_NEAR(fresnel_conductor(c, 1.5f, 0), fresnel_dielectric(c, 1.5f).unpolarized(), 1e-5f) << "cos " << c;
  EXPECT_NEAR(fresnel_conductor(0, 1.66f, 9.22f), 1.0f, 1e-5f);
}

// Veach 1997, Eq. 5.14: a BSDF for radiance obeys
// f(wo <- wi) / eta_o² = f(wi <- wo) / eta_i², eta the index on each
// direction's side; for reflection, plain symmetry.
TEST(render_fresnel, RoughDielectricObeysGeneralisedReciprocity) {
  const float ior = 1.33f;
  const DielectricBsdf rough(ior, 0.4f);
  int checked = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const float a = 0.07f * static_cast<float>(i), b = 0.08f * static_cast<float>(j);
      const Vec3 wo = normalize(Vec3{std::sin(a), 0.3f, std::cos(a)});
      const Vec3 wi = normalize(Vec3{std::sin(b) * std::cos(1.0f), std::sin(b) * std::sin(1.0f), std::cos(b)});
      if (std::abs(wo.z) < 0.05f || std::abs(wi.z) < 0.05f) continue;
      const float eta_o = wo.z > 0 ? 1 : ior, eta_i = wi.z > 0 ? 1 : ior;
      const float forward = rough.eval(wo, wi).g / (eta_o * eta_o), backward = rough.eval(wi, wo).g / (eta_i * eta_i);
      EXPECT_NEAR(forward, backward, 1e-4f * std::max(1.0f, forward)) << "wo.z " << wo.z << " wi.z " << wi.z;
      checked += forward > 0;
    }
  EXPECT_GT(checked, 500);
}
}  // namespace
}  // namespace dp::render
