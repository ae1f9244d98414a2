// Monte Carlo convergence: for an unbiased estimator with independent
// samples the RMSE against the converged image falls as spp^-1/2. The
// stratified (Owen-scrambled Sobol) sampler must do at least as well. A scene
// with every kind of vertex (diffuse floor, rough glass, smooth water,
// rough metal, an area light and a sky) is rendered at 4 ... 256 spp and
// compared with an independent (other seed) 4096-spp render; the slope of
// log RMSE over log spp must be -0.5 +- 0.1.
#include <gtest/gtest.h>

#include <cmath>

#include "render_image.h"
#include "render_scene.h"
#include "test_meshes.h"

namespace dp::render {
namespace {

dp::io::Material material(dp::io::MaterialType type, double roughness) {
  dp::io::Material m;
  m.type = type;
  m.roughness = m.fogged_roughness = m.wet_roughness = roughness;
  if (type == dp::io::MaterialType::Conductor) m.albedo = {1, 1, 1};
  return m;
}

TEST(render_convergence, RmseFallsAsInverseSquareRootOfSamples) {
  dp::io::Material lamp = material(dp::io::MaterialType::Diffuse, 0);
  lamp.albedo = {0, 0, 0};
  lamp.emission = {2, 1.8, 1.5};
  const RenderScene scene({{"floor", test::box({-2, -0.1f, -2}, {2, 0, 2}), material(dp::io::MaterialType::Diffuse, 0), ShadingNormals::Geometric},
                           {"glass", test::icosphere({-0.25f, 0.2f, 0}, 0.2f, 3), material(dp::io::MaterialType::Dielectric, 0.2), ShadingNormals::Interpolated},
                           {"drop", test::icosphere({0.25f, 0.15f, 0.1f}, 0.15f, 3), material(dp::io::MaterialType::Dielectric, 0), ShadingNormals::Interpolated},
                           {"metal", test::box({-0.1f, 0, -0.5f}, {0.3f, 0.3f, -0.3f}), material(dp::io::MaterialType::Conductor, 0.3), ShadingNormals::Geometric},
                           {"lamp", test::disk_facing_down({0, 1.2f, 0}, 0.6f, 32), lamp, ShadingNormals::Geometric}});
  dp::io::RenderSettings s;
  s.width = 24;
  s.height = 18;
  s.camera.position_m = {0.4, 0.8, 1.4};
  s.camera.look_at_m = {0, 0.15, 0};
  s.seed = 2;
  s.spp = 4096;
  s.sampler = dp::io::SamplerType::Independent;
  const Image reference = render_image(scene, s, 0).beauty;

  const auto rmse_of = [&](const Image& image) {
    double squared = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) squared += std::pow(image.pixels[i][c] - reference.pixels[i][c], 2);
    return std::sqrt(squared / (3.0 * static_cast<double>(image.pixels.size())));
  };

  s.seed = 1;
  s.sampler = dp::io::SamplerType::Independent;
  std::vector<double> log_spp, log_rmse;
  for (int spp : {4, 16, 64, 256}) {
    s.spp = spp;
    const double rmse = rmse_of(render_image(scene, s, 0).beauty);
    std::printf("%4d spp: RMSE %.5f\n", spp, rmse);
    log_spp.push_back(std::log(spp));
    log_rmse.push_back(std::log(rmse));
  }
  // Least-squares slope.
  const double n = static_cast<double>(log_spp.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < log_spp.size(); ++i) {
    sx += log_spp[i], sy += log_rmse[i], sxx += log_spp[i] * log_spp[i], sxy += log_spp[i] * log_rmse[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("fitted slope %.3f\n", slope);
  EXPECT_NEAR(slope, -0.5, 0.1);

  s.sampler = dp::io::SamplerType::Sobol;
  s.spp = 64;
  const double stratified = rmse_of(render_image(scene, s, 0).beauty);
  std::printf("64 spp, Owen-scrambled Sobol: RMSE %.5f (independent %.5f)\n", stratified, std::exp(log_rmse[2]));
  EXPECT_LE(stratified, std::exp(log_rmse[2]));
}

}  // namespace
}  // namespace dp::render
