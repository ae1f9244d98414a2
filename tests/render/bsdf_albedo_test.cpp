// Directional albedo E(mu) = ∫ f(wo, wi) |cos θi| dωi of the GGX BSDFs,
// estimated by sampling them, against Blender Cycles' published tables
// (intern/cycles/scene/shader.tables, computed by Cycles' own
// cycles_precompute.cpp with its own GGX code and 2^23 Sobol samples per
// entry):
//   table_ggx_E[y][x]        conductor with Fresnel 1, roughness r = x/31
//                            (alpha = r²), mu = y/31;
//   table_ggx_glass_E[z][y][x] dielectric, reflection + transmission
//                            without the 1/eta² radiance factor, r = x/15,
//                            mu = y/15, IOR = (1 + z'²)/(1 - z'²) with
//                            z' = z/15 (z = 6: IOR 1.380952).
// Both use the height-correlated Smith G, as ours does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "conductor_bsdf.h"
#include "dielectric_bsdf.h"
#include "random_stream.h"

namespace dp::render {
namespace {

struct TableEntry {
  int x, y;
  double albedo;
};

// Mean of sample weights: an unbiased estimate of the directional albedo.
// eta_squared_back undoes the radiance compression, as Cycles' tables do.
template <class Bsdf>
double sampled_albedo(const Bsdf& bsdf, float mu, int samples, bool undo_radiance_scaling) {
  const Vec3 wo{std::sqrt(std::max(0.0f, 1 - mu * mu)), 0, mu};
  double sum = 0;
  for (int i = 0; i < samples; ++i) {
    RandomStream random(11, 0, 0, static_cast<std::uint32_t>(i));
    const float u_lobe = random.uniform();
    const Sample2 u{random.uniform(), random.uniform()};
    const auto s = bsdf.sample(wo, u_lobe, u);
    if (!s) continue;
    sum += s->weight.g * (undo_radiance_scaling ? s->eta * s->eta : 1.0f);
  }
  return sum / samples;
}

constexpr int kSamples = 400000;
// Each weight lies in [0, 1], so the standard error is below 0.5/sqrt(N) = 0.0008.
constexpr double kTolerance = 0.004;

TEST(render_bsdf_albedo, GgxConductorMatchesCyclesTable) {
  // A conductor with k = 10^4 reflects 1 - O(1e-6) at every angle.
  const TableEntry entries[] = {{16, 16, 0.847421}, {31, 16, 0.443841}, {24, 8, 0.727744}, {20, 4, 0.852774}};
  for (const TableEntry& e : entries) {
    const float r = static_cast<float>(e.x) / 31, mu = static_cast<float>(e.y) / 31;
    const ConductorBsdf perfect(Rgb::gray(1), Rgb::gray(1e4f), Rgb::gray(1), r * r);
    const double estimate = sampled_albedo(perfect, mu, kSamples, false);
    std::printf("conductor alpha %.4f mu %.4f: sampled %.5f, Cycles %.5f\n", r * r, mu, estimate, e.albedo);
    EXPECT_NEAR(estimate, e.albedo, kTolerance) << "x " << e.x << " y " << e.y;
  }
}

TEST(render_bsdf_albedo, GgxDielectricMatchesCyclesGlassTable) {
  const float ior = (1 + 0.16f) / (1 - 0.16f);  // z = 6: F0 = (6/15)^4
  const TableEntry entries[] = {{5, 5, 0.977385}, {10, 5, 0.874868}, {15, 5, 0.706761},
                                {5, 10, 0.995624}, {10, 10, 0.941336}, {15, 10, 0.801176}};
  for (const TableEntry& e : entries) {
    const float r = static_cast<float>(e.x) / 15, mu = static_cast<float>(e.y) / 15;
    const DielectricBsdf glass(ior, r * r);
    const double estimate = sampled_albedo(glass, mu, kSamples, true);
    std::printf("dielectric alpha %.4f mu %.4f: sampled %.5f, Cycles %.5f\n", r * r, mu, estimate, e.albedo);
    EXPECT_NEAR(estimate, e.albedo, kTolerance) << "x " << e.x << " y " << e.y;
  }
}

// The sampled estimate must be of the same f that eval() returns: the
// albedo by quadrature of eval over the sphere agrees.
TEST(render_bsdf_albedo, EvalIntegratesToTheSampledAlbedo) {
  const float ior = 1.33f, alpha = 0.5f, mu = 0.6f;
  const DielectricBsdf water(ior, alpha);
  const ConductorBsdf metal(Rgb::gray(1.5f), Rgb::gray(4), Rgb::gray(1), alpha);
  const Vec3 wo{std::sqrt(1 - mu * mu), 0, mu};
  const int n = 600;
  double water_sum = 0, metal_sum = 0;
  for (int i = 0; i < 2 * n; ++i) {
    const float c = -1 + (static_cast<float>(i) + 0.5f) / n;
    const float s = std::sqrt(1 - c * c);
    for (int j = 0; j < n; ++j) {
      const float phi = 2 * 3.14159265f * (static_cast<float>(j) + 0.5f) / n;
      const Vec3 wi{s * std::cos(phi), s * std::sin(phi), c};
      water_sum += water.eval(wo, wi).g * std::abs(c);
      metal_sum += metal.eval(wo, wi).g * std::abs(c);
    }
  }
  const double cell = (1.0 / n) * (2 * 3.14159265358979 / n);
  EXPECT_NEAR(water_sum * cell, sampled_albedo(water, mu, kSamples, false), kTolerance);
  EXPECT_NEAR(metal_sum * cell, sampled_albedo(metal, mu, kSamples, false), kTolerance);
}

}  // namespace
}  // namespace dp::render
