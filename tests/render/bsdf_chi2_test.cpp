// Sampling against evaluation: directions drawn by a BSDF's sample() must
// be distributed as its pdf() says. Pearson's chi-square test over a
// sphere of equal-solid-angle cells (the test Mitsuba and pbrt apply to
// their BSDFs), with expected counts from integrating pdf() over each
// cell; cells expecting fewer than 5 samples are pooled, and samples that
// sample() declines form a cell of their own.
#include <gtest/gtest.h>

#include <boost/math/special_functions/gamma.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "conductor_bsdf.h"
#include "dielectric_bsdf.h"
#include "random_stream.h"

namespace dp::render {
namespace {

constexpr int kCosBins = 24, kPhiBins = 48, kSubdivisions = 8, kEdgeSubdivisions = 128;
constexpr int kSamples = 300000;
constexpr int kTests = 12;
// Bonferroni: a 1 % chance of any false alarm over the whole suite.
constexpr double kSignificance = 0.01 / kTests;

Vec3 direction(double cos_theta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  return {static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(cos_theta)};
}

int cell_of(Vec3 w) {
  const double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
  const int ci = std::clamp(static_cast<int>((w.z + 1) / 2 * kCosBins), 0, kCosBins - 1);
  const int pi = std::clamp(static_cast<int>((phi < 0 ? phi + 2 * std::numbers::pi : phi) / (2 * std::numbers::pi) * kPhiBins), 0, kPhiBins - 1);
  return ci * kPhiBins + pi;
}

template <class Bsdf>
double chi_square_p_value(const Bsdf& bsdf, Vec3 wo) {
  std::vector<double> observed(kCosBins * kPhiBins + 1, 0);  // last: declined
  for (int i = 0; i < kSamples; ++i) {
    RandomStream random(3, 1, 2, static_cast<std::uint32_t>(i));
    const float u_lobe = random.uniform();
    const auto s = bsdf.sample(wo, u_lobe, {random.uniform(), random.uniform()});
    observed[s ? static_cast<std::size_t>(cell_of(s->wi)) : observed.size() - 1] += 1;
  }
  std::vector<double> expected(observed.size(), 0);
  const double d_cos = 2.0 / kCosBins, d_phi = 2 * std::numbers::pi / kPhiBins;
  double total = 0;
  for (int ci = 0; ci < kCosBins; ++ci)
    for (int pi = 0; pi < kPhiBins; ++pi) {
      // Midpoint rule; a cell the pdf's support boundary crosses, where
      // refraction piles directions up towards the critical angle (an
      // integrable singularity), is integrated on a much finer grid.
      const auto integrate = [&](int n, bool* irregular) {
        double integral = 0, largest = 0;
        int zeros = 0;
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n; ++b) {
            const double c = -1 + d_cos * (ci + (a + 0.5) / n);
            const double phi = d_phi * (pi + (b + 0.5) / n);
            const double p = bsdf.pdf(wo, direction(c, phi));
            integral += p;
            largest = std::max(largest, p);
            zeros += p == 0;
          }
        if (irregular) *irregular = zeros > 0 && largest > 0;
        return integral * (d_cos / n) * (d_phi / n);
      };
      bool irregular = false;
      double integral = integrate(kSubdivisions, &irregular);
      if (irregular) integral = integrate(kEdgeSubdivisions, nullptr);
      expected[static_cast<std::size_t>(ci * kPhiBins + pi)] = integral * kSamples;
      total += integral;
    }
  expected.back() = std::max(0.0, 1 - total) * kSamples;

  double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
  int cells = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      continue;
    }
    const double term = (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    if (term > 20) std::printf("    cell cos %d phi %d: observed %.0f expected %.1f\n", static_cast<int>(i) / kPhiBins, static_cast<int>(i) % kPhiBins, observed[i], expected[i]);
    chi2 += term;
    ++cells;
  }
  if (pooled_expected >= 5) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++cells;
  } else {
    // A few stray samples where pdf() sees (almost) nothing would go unnoticed otherwise.
    EXPECT_LT(pooled_observed, 5 + 5 * pooled_expected) << "samples where pdf() is ~0";
  }
  const double p = boost::math::gamma_q(0.5 * (cells - 1), 0.5 * chi2);
  std::printf("  chi2 %.1f over %d cells, p = %.4f (pdf integral %.5f)\n", chi2, cells, p, total);
  return p;
}

Vec3 at_angle(float degrees, bool inside) {
  const float t = degrees * std::numbers::pi_v<float> / 180;
  return {std::sin(t), 0, inside ? -std::cos(t) : std::cos(t)};
}

TEST(render_bsdf_chi2, GgxConductorSamplesItsPdf) {
  for (float alpha : {0.3f, 0.7f})
    for (float theta : {30.0f, 70.0f}) {
      std::printf("conductor alpha %.1f theta_o %.0f\n", alpha, theta);
      const ConductorBsdf metal(Rgb::gray(0.2f), Rgb::gray(3), Rgb::gray(1), alpha);
      EXPECT_GT(chi_square_p_value(metal, at_angle(theta, false)), kSignificance) << alpha << " " << theta;
    }
}

TEST(render_bsdf_chi2, GgxDielectricSamplesItsPdf) {
  for (float alpha : {0.3f, 0.7f})
    for (bool inside : {false, true})
      for (float theta : {30.0f, 65.0f}) {
        std::printf("dielectric alpha %.1f theta_o %.0f %s\n", alpha, theta, inside ? "inside" : "outside");
        const DielectricBsdf water(1.33f, alpha);
        EXPECT_GT(chi_square_p_value(water, at_angle(theta, inside)), kSignificance) << alpha << " " << theta << " " << inside;
      }
}

}  // namespace
}  // namespace dp::render
