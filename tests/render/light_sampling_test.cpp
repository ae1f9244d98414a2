// Light sampling against closed forms. A Lambertian point under a uniformly
// emitting disk of radiance L, radius r, at height h on its axis receives
// irradiance E = pi L r² / (r² + h²) (r²/(r² + h²) being the view factor
// from a point to a coaxial parallel disk), so it reflects
// albedo L r² / (r² + h²). Under an environment map that is constant over
// each pixel's patch of directions, an upward plane receives
// E = sum over pixels of L_pixel (sin²θ1 - sin²θ0)/2 Δφ, integrated here
// pixel by pixel without the renderer's sampling code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "image_environment.h"
#include "piecewise_constant.h"
#include "random_stream.h"
#include "render_image.h"
#include "render_scene.h"
#include "sky_environment.h"
#include "test_meshes.h"

namespace dp::render {
namespace {

dp::io::Material diffuse(double albedo) {
  dp::io::Material m;
  m.albedo = {albedo, albedo, albedo};
  return m;
}

// A small image of the point at the origin, seen from the side.
dp::io::RenderSettings close_up_of_origin(int spp) {
  dp::io::RenderSettings s;
  s.width = s.height = 16;
  s.spp = spp;
  s.max_depth = 4;
  s.camera.position_m = {0.6, 0.3, 0.1};
  s.camera.look_at_m = {0, 0, 0};
  s.camera.fov_deg = 0.5;  // a footprint of ~6 mm, over which E changes by < 1e-4
  return s;
}

double mean_green(const Image& image) {
  double sum = 0;
  for (const Rgb& p : image.pixels) sum += p.g;
  return sum / static_cast<double>(image.pixels.size());
}

TEST(render_light_sampling, DiskLightOverLambertianPlaneMatchesViewFactor) {
  const double albedo = 0.5, radiance = 3, height = 1;
  for (double radius : {0.5, 0.05}) {
    dp::io::Material light = diffuse(0);
    light.emission = {radiance, radiance, radiance};
    const RenderScene scene({{"floor", test::box({-50, -1, -50}, {50, 0, 50}), diffuse(albedo), ShadingNormals::Geometric},
                             {"lamp", test::disk_facing_down({0, static_cast<float>(height), 0}, static_cast<float>(radius), 256),
                              light, ShadingNormals::Geometric}});
    const ConstantEnvironment black(Rgb{});
    const double measured = mean_green(render_image(scene, black, close_up_of_origin(64), 0).beauty);
    const double r2 = radius * radius;
    const double expected = albedo * radiance * r2 / (r2 + height * height);
    std::printf("disk r = %.2f m: measured %.6f, view factor gives %.6f\n", radius, measured, expected);
    EXPECT_NEAR(measured, expected, 0.01 * expected) << "radius " << radius;
  }
}

// A dim sky with a small bright sun, below the horizon dark ground.
std::vector<Rgb> sun_and_sky(int width, int height) {
  std::vector<Rgb> pixels(static_cast<std::size_t>(width * height));
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col) {
      Rgb& p = pixels[static_cast<std::size_t>(row * width + col)];
      p = row < height / 2 ? Rgb{0.2f, 0.3f, 0.5f} : Rgb{0.05f, 0.04f, 0.03f};
      if (row >= 6 && row < 8 && col >= 40 && col < 44) p = Rgb{60, 55, 50};
    }
  return pixels;
}

TEST(render_light_sampling, EnvironmentMapOverLambertianPlaneMatchesPixelIntegral) {
  const int w = 64, h = 32;
  const std::vector<Rgb> pixels = sun_and_sky(w, h);
  const ImageEnvironment environment(pixels, w, h, 1, 30);
  const double albedo = 0.5;
  const RenderScene scene({{"floor", test::box({-50, -1, -50}, {50, 0, 50}), diffuse(albedo), ShadingNormals::Geometric}});
  dp::io::RenderSettings settings = close_up_of_origin(64);
  settings.camera.position_m = {0.3, 1, 0.2};
  const double measured = mean_green(render_image(scene, environment, settings, 0).beauty);

  double irradiance = 0;
  const double d_phi = 2 * std::numbers::pi / w;
  for (int row = 0; row < h / 2; ++row) {
    const double t0 = std::numbers::pi * row / h, t1 = std::numbers::pi * (row + 1) / h;
    const double patch = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) * d_phi;
    for (int col = 0; col < w; ++col) irradiance += pixels[static_cast<std::size_t>(row * w + col)].g * patch;
  }
  const double expected = albedo / std::numbers::pi * irradiance;
  std::printf("environment map: measured %.6f, pixel integral gives %.6f\n", measured, expected);
  EXPECT_NEAR(measured, expected, 0.01 * expected);
}

TEST(render_light_sampling, EnvironmentMapSamplesFollowTheirPdf) {
  // The density sample() reports is the one pdf() gives for that direction,
  // and it integrates to one over the sphere.
  const int w = 64, h = 32;
  const ImageEnvironment environment(sun_and_sky(w, h), w, h, 1, 30);
  for (std::uint32_t i = 0; i < 1000; ++i) {
    RandomStream random(9, 0, 0, i);
    const EnvironmentSample s = environment.sample({random.uniform(), random.uniform()});
    ASSERT_GT(s.pdf, 0);
    EXPECT_NEAR(environment.pdf(s.direction), s.pdf, 1e-3f * s.pdf);
    const Rgb l = environment.radiance(s.direction);
    EXPECT_EQ(l.g, s.radiance.g);
  }
  const int n = 800;
  double integral = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < 2 * n; ++b) {
      const double z = -1 + (a + 0.5) / n * 2, phi = 2 * std::numbers::pi * (b + 0.5) / (2 * n), r = std::sqrt(1 - z * z);
      integral += environment.pdf({static_cast<float>(r * std::cos(phi)), static_cast<float>(z), static_cast<float>(r * std::sin(phi))});
    }
  integral *= (2.0 / n) * (2 * std::numbers::pi / (2 * n));
  EXPECT_NEAR(integral, 1.0, 0.01);
}

TEST(render_light_sampling, PiecewiseConstantPicksCellsByWeight) {
  const PiecewiseConstant1D d({1, 0, 3, 4});
  std::vector<double> counts(4, 0);
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    RandomStream random(1, 2, 3, static_cast<std::uint32_t>(i));
    const auto s = d.sample_continuous(random.uniform());
    counts[s.cell] += 1;
    ASSERT_EQ(s.cell, static_cast<std::size_t>(s.x * 4));
  }
  const double expected[4] = {0.125, 0, 0.375, 0.5};
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(counts[static_cast<std::size_t>(c)] / n, expected[c], 0.005) << "cell " << c;
  EXPECT_FLOAT_EQ(d.pdf(0.6f), 0.375f * 4);
}

}  // namespace
}  // namespace dp::render
