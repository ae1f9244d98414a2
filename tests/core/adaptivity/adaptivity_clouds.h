#pragma once
// Particle clouds for the adaptivity tests, and the conserved totals they are
// checked against, computed on the host in double.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "sph/adaptivity_winchenbach2017_driver.h"

namespace dp::test {

struct HostParticles {
  std::vector<Vec3> position, velocity;
  std::vector<float> temperature;
  std::vector<MassUnits> units;
  std::vector<std::uint32_t> id;
  std::vector<float> extra;
  std::size_t extra_count = 0;
  std::size_t size() const { return units.size(); }
};

template <class Exec>
AdaptiveParticles<Exec> to_device(const HostParticles& h) {
  AdaptiveParticles<Exec> d;
  Exec::upload(d.position, h.position);
  Exec::upload(d.velocity, h.velocity);
  Exec::upload(d.temperature, h.temperature);
  Exec::upload(d.units, h.units);
  Exec::upload(d.id, h.id);
  Exec::upload(d.extra, h.extra);
  d.extra_count = h.extra_count;
  return d;
}

template <class Exec>
HostParticles to_host(const AdaptiveParticles<Exec>& d) {
  HostParticles h;
  h.position = Exec::download(d.position);
  h.velocity = Exec::download(d.velocity);
  h.temperature = Exec::download(d.temperature);
  h.units = Exec::download(d.units);
  h.id = Exec::download(d.id);
  h.extra = Exec::download(d.extra);
  h.extra_count = d.extra_count;
  return h;
}

// SPH sampling of the tests: spacing s, support radius h = 2 s.
inline constexpr float kSpacing = 0.01f;
inline constexpr float kSupport = 2.0f * kSpacing;
inline constexpr float kBoxOffset = 0.05f;  // keeps positions away from 0, where relative errors mislead

// Side of a cube holding n particles at the rest spacing.
inline float box_side(std::size_t n) { return std::cbrt(static_cast<float>(n)) * kSpacing; }

inline UniformGrid grid_for_box(float side) {
  UniformGrid g;
  g.origin = Vec3{0, 0, 0};
  g.cell_size = kSupport;
  g.nx = g.ny = g.nz = static_cast<int>(std::ceil((side + 2 * kBoxOffset) / kSupport)) + 1;
  return g;
}

// n particles uniformly in the box, units from `units_at(i, rng)`, random
// velocities around a mean flow (so that total momentum is not near zero),
// random temperatures and one extra attribute.
template <class UnitsAt>
HostParticles random_cloud(std::size_t n, unsigned seed, UnitsAt units_at) {
  std::mt19937 rng(seed);
  const float side = box_side(n);
  std::uniform_real_distribution<float> coord(kBoxOffset, kBoxOffset + side);
  std::uniform_real_distribution<float> speed(-1.0f, 1.0f);
  std::uniform_real_distribution<float> temp(280.0f, 370.0f);
  HostParticles h;
  h.extra_count = 1;
  for (std::size_t i = 0; i < n; ++i) {
    h.position.push_back(Vec3{coord(rng), coord(rng), coord(rng)});
    h.velocity.push_back(Vec3{0.5f + speed(rng), -0.3f + speed(rng), 0.2f + speed(rng)});
    h.temperature.push_back(temp(rng));
    h.units.push_back(units_at(i, rng));
    h.id.push_back(static_cast<std::uint32_t>(i));
    h.extra.push_back(speed(rng));
  }
  return h;
}

// Weights uniform in (0, 1].
inline HostParticles random_weight_cloud(std::size_t n, unsigned seed) {
  return random_cloud(n, seed, [](std::size_t, std::mt19937& rng) {
    return std::uniform_int_distribution<MassUnits>(1, kFullParticleUnits)(rng);
  });
}

// Half the particles full, half at w = 0.1, interleaved at random positions.
inline HostParticles bimodal_cloud(std::size_t n, unsigned seed) {
  return random_cloud(n, seed, [](std::size_t i, std::mt19937&) {
    return i % 2 == 0 ? kFullParticleUnits : kFullParticleUnits / 10;
  });
}

struct DVec3 {
  double x = 0, y = 0, z = 0;
};

inline double distance(DVec3 a, DVec3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}
inline double norm(DVec3 a) { return distance(a, DVec3{}); }

// Totals weighted by mass units, in units of a full particle.
struct Totals {
  std::uint64_t units = 0;
  DVec3 momentum;        // sum w v
  double momentum_scale = 0;  // sum w |v|: the scale momentum errors are measured against
  DVec3 first_moment;    // sum w x (centre of mass times total weight)
  double heat = 0;       // sum w T
  double extra = 0;      // sum w e
};

inline Totals totals_of(const HostParticles& h) {
  Totals t;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double w = static_cast<double>(h.units[i]) / kFullParticleUnits;
    t.units += h.units[i];
    t.momentum.x += w * h.velocity[i].x;
    t.momentum.y += w * h.velocity[i].y;
    t.momentum.z += w * h.velocity[i].z;
    t.momentum_scale += w * std::sqrt(double(h.velocity[i].x) * h.velocity[i].x +
                                      double(h.velocity[i].y) * h.velocity[i].y +
                                      double(h.velocity[i].z) * h.velocity[i].z);
    t.first_moment.x += w * h.position[i].x;
    t.first_moment.y += w * h.position[i].y;
    t.first_moment.z += w * h.position[i].z;
    t.heat += w * h.temperature[i];
    for (std::size_t a = 0; a < h.extra_count; ++a) t.extra += w * h.extra[a * h.size() + i];
  }
  return t;
}

inline std::size_t count_below(const HostParticles& h, double weight) {
  std::size_t c = 0;
  for (MassUnits u : h.units) c += static_cast<double>(u) / kFullParticleUnits < weight ? 1 : 0;
  return c;
}

}  // namespace dp::test
