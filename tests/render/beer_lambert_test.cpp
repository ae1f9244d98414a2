// Light crossing an absorbing dielectric slab at normal incidence: each
// boundary transmits T = 1 - R, R = ((n-1)/(n+1))^2, and the inside keeps
// exp(-sigma d). The sky is black but for its zenith, so only the straight
// path through the slab (and, 1e-3 of it, its inter-reflections) gathers
// light.
#include <gtest/gtest.h>

#include <cmath>

#include "path_tracer.h"
#include "sky_environment.h"
#include "test_meshes.h"

namespace dp::render {
namespace {

TEST(render_beer_lambert, SlabTransmitsFresnelTimesExponential) {
  const double n = 1.33, thickness_m = 0.5;
  const double sigma[3] = {2.0, 0.6, 0.3};
  dp::io::Material water;
  water.type = dp::io::MaterialType::Dielectric;
  water.ior = n;
  water.absorption_per_m = {sigma[0], sigma[1], sigma[2]};
  // Wide enough that no path reaches the sides; flat-shaded, so the slab's
  // inside is where Embree's geometric normal says (counter-clockwise winding).
  const RenderScene scene({{"slab", test::box({-100, 0, -100}, {100, static_cast<float>(thickness_m), 100}), water,
                            ShadingNormals::Geometric}});
  dp::io::EnvironmentSettings zenith_only;
  zenith_only.zenith = {1, 1, 1};
  zenith_only.horizon = zenith_only.ground = {0, 0, 0};
  const SkyEnvironment sky(zenith_only);
  const PathTracer tracer(scene, sky, 12);

  const int samples = 200000;
  double sum[3] = {0, 0, 0};
  for (int i = 0; i < samples; ++i) {
    RandomStream random(7, 0, 0, static_cast<std::uint32_t>(i));
    const Rgb l = tracer.radiance({{0, -1, 0}, {0, 1, 0}}, random);
    for (int c = 0; c < 3; ++c) sum[c] += l[c];
  }

  const double r = std::pow((n - 1) / (n + 1), 2), t = 1 - r;
  for (int c = 0; c < 3; ++c) {
    const double estimate = sum[c] / samples;
    const double single_pass = t * t * std::exp(-sigma[c] * thickness_m);
    // Light reflected back and forth inside adds a geometric series.
    const double all_passes = single_pass / (1 - r * r * std::exp(-2 * sigma[c] * thickness_m));
    std::printf("channel %d: estimate %.6f, T^2 exp(-sigma d) %.6f, with inter-reflections %.6f\n", c, estimate,
                single_pass, all_passes);
    EXPECT_NEAR(estimate, single_pass, 0.01 * single_pass) << "channel " << c;
    EXPECT_NEAR(estimate, all_passes, 0.003 * all_passes) << "channel " << c;
  }
}

}  // namespace
}  // namespace dp::render
