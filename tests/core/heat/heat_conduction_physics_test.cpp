// Heat conduction (Cleary & Monaghan 1999; paper Eq. 9) against the
// analytic solutions for two bodies brought into contact (Carslaw & Jaeger,
// Conduction of Heat in Solids, 1959): particles on a static lattice
// form a bar along x, one block at x < 0 and one at x > 0.
//
// The bar's ends and lateral faces are insulated, as in SPH without
// neighbours there; the profile stays one-dimensional as long as the
// diffusion length 2 sqrt(alpha t) is well below the half-length, so the
// infinite-bar solutions apply at every particle, lateral faces included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "heat_scene.h"
#include "sph/heat_cleary_monaghan1999.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"

namespace dp {
namespace {

using heat_test::lattice_block;
using heat_test::SortedSet;

struct Material {
  float conductivity;   // W/(m K)
  float density;        // kg/m^3
  float specific_heat;  // J/(kg K)
  double diffusivity() const { return double(conductivity) / (double(density) * specific_heat); }
  double effusivity() const { return std::sqrt(double(conductivity) * density * specific_heat); }
};

constexpr Material kWater{0.6f, 1000.0f, 4186.0f};
// A solid with twice water's effusivity and four times its diffusivity, so
// that the contact temperature differs clearly from both the mean and
// either initial temperature, and both sides' profiles span several
// particles at once.
constexpr Material kStone{2.4f, 2000.0f, 2093.0f};

constexpr float kSpacing = 0.01f;  // m
constexpr int kHalfLength = 60;    // particles per block along x
constexpr int kSection = 6;        // particles across
constexpr float kCold = 293.15f, kHot = 353.15f;  // K

struct ThermalBlock {
  std::vector<Vec3> position;
  std::vector<float> temperature;  // initial
  Material material;
  bool rigid;
};

struct Conduction {
  std::vector<std::vector<float>> temperature;  // per block, lattice order
  double energy_start = 0, energy_end = 0;      // sum m C T, J
  double time = 0;                              // s
  int steps = 0;
};

double thermal_energy(const ThermalParticles& p, std::size_t n) {
  double e = 0;
  for (std::size_t i = 0; i < n; ++i)
    e += double(p.mass_of(static_cast<std::uint32_t>(i))) * p.specific_heat * p.temperature[i];
  return e;
}

// Explicit Euler at the stability limit of heat_time_step_limit, rates of
// all blocks from the same old temperatures.
Conduction conduct(const std::vector<ThermalBlock>& blocks, double duration, int threads) {
  CpuExec exec(threads);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * kSpacing);
  std::vector<std::vector<Vec3>> positions;
  for (const auto& b : blocks) positions.push_back(b.position);
  const UniformGrid grid = heat_test::grid_around(positions, kernel.h);

  const std::size_t count = blocks.size();
  std::vector<SortedSet> sets;
  std::vector<std::vector<float>> temperature(count), rate(count), density(count), volume(count);
  std::vector<std::vector<MassUnits>> units(count);
  for (std::size_t s = 0; s < count; ++s) {
    sets.push_back(heat_test::sort_into(exec, blocks[s].position, grid));
    std::size_t n = blocks[s].position.size();
    temperature[s] = sets[s].to_sorted(blocks[s].temperature);
    rate[s].assign(n, 0.0f);
    units[s].assign(n, kFullParticleUnits);
    density[s].assign(n, blocks[s].material.density);
    volume[s].assign(n, kSpacing * kSpacing * kSpacing);
  }
  std::vector<ThermalParticles> particles;
  std::vector<heat_test::MassesAndVolumes> liquid(count);
  for (std::size_t s = 0; s < count; ++s) {
    const Material& m = blocks[s].material;
    if (blocks[s].rigid) {
      particles.push_back(ThermalParticles::rigid(sets[s].view(), temperature[s].data(), volume[s].data(), m.density,
                                                  m.conductivity, m.specific_heat));
      continue;
    }
    liquid[s] = heat_test::masses_and_volumes(units[s], density[s], m.density * volume[s][0]);
    particles.push_back(ThermalParticles::liquid(sets[s].view(), temperature[s].data(), liquid[s].mass.data(),
                                                 liquid[s].volume.data(), m.conductivity, m.specific_heat));
  }

  float dt = 1e30f;
  for (std::size_t s = 0; s < count; ++s) {
    const Material& m = blocks[s].material;
    float kappa = m.conductivity;
    if (count == 2) {
      const Material& o = blocks[1 - s].material;
      kappa = std::max(kappa, 2.0f * m.conductivity * o.conductivity / (m.conductivity + o.conductivity));
    }
    dt = std::min(dt, heat_time_step_limit(kernel, m.density, m.specific_heat, kappa));
  }
  Conduction r;
  r.steps = static_cast<int>(std::ceil(duration / dt));
  dt = static_cast<float>(duration / r.steps);
  r.time = double(dt) * r.steps;

  auto energy = [&] {
    double e = 0;
    for (std::size_t s = 0; s < count; ++s) e += thermal_energy(particles[s], sets[s].size());
    return e;
  };
  r.energy_start = energy();
  for (int step = 0; step < r.steps; ++step) {
    for (std::size_t s = 0; s < count; ++s)
      exec.parallel_for(sets[s].size(), ComputeTemperatureRate{particles[s], particles[count == 2 ? 1 - s : s],
                                                               count == 2, kernel, rate[s].data()});
    for (std::size_t s = 0; s < count; ++s)
      exec.parallel_for(sets[s].size(), IntegrateTemperature{rate[s].data(), nullptr, dt, temperature[s].data()});
  }
  r.energy_end = energy();
  for (std::size_t s = 0; s < count; ++s) r.temperature.push_back(sets[s].to_lattice(temperature[s]));
  return r;
}

ThermalBlock block(bool left, Material m, float t0, bool rigid) {
  const float x0 = left ? -(kHalfLength - 0.5f) * kSpacing : 0.5f * kSpacing;
  ThermalBlock b{lattice_block(Vec3{x0, 0, 0}, kHalfLength, kSection, kSection, kSpacing), {}, m, rigid};
  b.temperature.assign(b.position.size(), t0);
  return b;
}

// Duration for which the faster-diffusing material's sqrt(alpha t) is
// `lengths` spacings.
double time_for_diffusion_length(double alpha, double lengths) {
  double l = lengths * kSpacing;
  return l * l / alpha;
}

TEST(heat_Conduction, BarProfileMatchesErfSolution) {
  ThermalBlock bar = block(true, kWater, kCold, false);
  ThermalBlock right = block(false, kWater, kHot, false);
  bar.position.insert(bar.position.end(), right.position.begin(), right.position.end());
  bar.temperature.insert(bar.temperature.end(), right.temperature.begin(), right.temperature.end());

  const double alpha = kWater.diffusivity();
  Conduction r = conduct({bar}, time_for_diffusion_length(alpha, 8.0), 4);

  const double root = 2.0 * std::sqrt(alpha * r.time);
  double max_error = 0, max_error_inner = 0;
  for (std::size_t i = 0; i < bar.position.size(); ++i) {
    const Vec3 x = bar.position[i];
    double exact = 0.5 * (kCold + kHot) + 0.5 * (kHot - kCold) * std::erf(x.x / root);
    double error = std::fabs(r.temperature[0][i] - exact) / (kHot - kCold);
    max_error = std::max(max_error, error);
    const float last = (kSection - 1) * kSpacing;
    bool inner = x.y > 0.5f * kSpacing && x.y < last - 0.5f * kSpacing && x.z > 0.5f * kSpacing &&
                 x.z < last - 0.5f * kSpacing;
    if (inner) max_error_inner = std::max(max_error_inner, error);
  }
  const double drift = std::fabs(r.energy_end - r.energy_start) / r.energy_start;
  std::printf("erf bar: t = %.0f s in %d steps, sqrt(alpha t) = %.1f spacings; max |T - T_exact| / dT = %.4f "
              "(all particles), %.4f (off the lateral faces); energy drift %.2e\n",
              r.time, r.steps, std::sqrt(alpha * r.time) / kSpacing, max_error, max_error_inner, drift);
  RecordProperty("max_error_fraction", std::to_string(max_error));
  RecordProperty("energy_drift", std::to_string(drift));
  EXPECT_LT(max_error, 0.05);
  EXPECT_LT(drift, 1e-6);
}

TEST(heat_Conduction, TwoMaterialsMeetAtTheContactTemperature) {
  const Material& a = kWater;
  const Material& b = kStone;
  ThermalBlock liquid = block(true, a, kCold, false);
  ThermalBlock rigid = block(false, b, kHot, true);
  Conduction r = conduct({liquid, rigid}, time_for_diffusion_length(b.diffusivity(), 8.0), 4);

  const double ea = a.effusivity(), eb = b.effusivity();
  const double contact = (ea * kCold + eb * kHot) / (ea + eb);
  const double ra = 2.0 * std::sqrt(a.diffusivity() * r.time), rb = 2.0 * std::sqrt(b.diffusivity() * r.time);
  auto exact = [&](double x) {
    return x < 0 ? kCold + (contact - kCold) * std::erfc(-x / ra) : kHot + (contact - kHot) * std::erfc(x / rb);
  };

  double max_error = 0;
  double next_to_contact[2] = {0, 0};
  int layer_count[2] = {0, 0};
  for (int s = 0; s < 2; ++s) {
    const ThermalBlock& blk = s == 0 ? liquid : rigid;
    for (std::size_t i = 0; i < blk.position.size(); ++i) {
      double t = r.temperature[s][i];
      max_error = std::max(max_error, std::fabs(t - exact(blk.position[i].x)) / (kHot - kCold));
      if (std::fabs(blk.position[i].x) < kSpacing) {
        next_to_contact[s] += t;
        ++layer_count[s];
      }
    }
    next_to_contact[s] /= layer_count[s];
  }
  // The interface lies half a spacing from the layers on either side; the
  // temperature there that passes the same flux into both materials.
  const double measured_contact = (a.conductivity * next_to_contact[0] + b.conductivity * next_to_contact[1]) /
                                  (a.conductivity + b.conductivity);
  const double contact_error = std::fabs(measured_contact - contact) / (kHot - kCold);
  const double drift = std::fabs(r.energy_end - r.energy_start) / r.energy_start;
  std::printf("two materials: e_b / e_a = %.3f, T_c exact %.4f K, SPH %.4f K, error %.2e of dT; "
              "max profile error %.4f; energy drift %.2e (%d steps)\n",
              eb / ea, contact, measured_contact, contact_error, max_error, drift, r.steps);
  RecordProperty("contact_error_fraction", std::to_string(contact_error));
  RecordProperty("max_error_fraction", std::to_string(max_error));
  RecordProperty("energy_drift", std::to_string(drift));
  EXPECT_LT(contact_error, 0.05);
  EXPECT_LT(max_error, 0.05);
  EXPECT_LT(drift, 1e-6);
}

}  // namespace
}  // namespace dp
