// Viscosity of Morris et al. 1997 against the analytic start-up of plane
// Poiseuille flow, the case Morris et al. validated it on (J. Comput. Phys.
// 136, Sec. 4.1, their Eq. 21): liquid at rest between two no-slip plates
// a distance L apart is driven along x by a body force F from t = 0;
//
//   u(y, t) = F/(2 nu) y (L - y)
//             - sum_n 4 F L^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi y / L) exp(-(2n+1)^2 pi^2 nu t / L^2).
//
// The flow is along x and varies only across y, so u . grad u = 0 and the
// particles' positions do not matter: the liquid is a static lattice whose
// velocities follow dv/dt = a_visc + F (as the heat tests keep a static
// lattice for conduction). It is periodic in x and z through ghost copies
// of the columns at the other end, which take their originals' velocities
// after every step. Each plate is one layer of boundary particles (Akinci
// 2012) at y = 0 and y = L, as the simulator's walls are, with the volumes
// ComputeBoundaryVolume gives them; the liquid's layers lie one spacing
// from the plates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../sorted_particles.h"
#include "sph/boundary_akinci2012.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/viscosity_morris1997.h"

namespace dp {
namespace {

// Morris et al. 1997, Sec. 4.1: L = 1 mm, nu = 1e-6 m^2/s, F = 2e-4 m/s^2.
constexpr double kGap = 1e-3;        // L, m
constexpr double kNu = 1e-6;         // m^2/s
constexpr double kForce = 2e-4;      // m/s^2
constexpr double kDensity = 1000.0;  // kg/m^3
constexpr int kPeriod = 4;           // liquid columns per period along x and z
constexpr int kGhosts = 2;           // ghost columns on each side (the support is two spacings)
constexpr int kWallMargin = 4;       // plate particles beyond the ghosts, so that V_b is a plate's

double analytic_velocity(double y, double t) {
  double u = kForce / (2 * kNu) * y * (kGap - y);
  const double pi = 3.14159265358979323846;
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    u -= 4 * kForce * kGap * kGap / (kNu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / kGap) *
         std::exp(-k * k * pi * pi * kNu * t / (kGap * kGap));
  }
  return u;
}

struct Profile {
  double time;                   // s
  std::vector<double> velocity;  // u_x per liquid layer, m/s
};

struct Channel {
  int layers;                    // liquid layers across the gap
  float spacing;                 // L / (layers + 1)
  std::vector<Vec3> liquid;      // lattice order: x fastest, then y, then z
  std::vector<std::size_t> source;  // per liquid particle, the core particle whose velocity it carries
  std::vector<Vec3> plates;
  std::vector<float> layer_y;    // m

  int columns() const { return kPeriod + 2 * kGhosts; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(columns()) * (j + static_cast<std::size_t>(layers) * k);
  }
};

Channel make_channel(int layers) {
  Channel c;
  c.layers = layers;
  c.spacing = static_cast<float>(kGap / (layers + 1));
  const float s = c.spacing;
  const int n = c.columns();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < layers; ++j)
      for (int i = 0; i < n; ++i) {
        c.liquid.push_back(Vec3{(i - kGhosts) * s, (j + 1) * s, (k - kGhosts) * s});
        auto wrap = [](int a) { return ((a - kGhosts) % kPeriod + kPeriod) % kPeriod + kGhosts; };
        c.source.push_back(c.index(wrap(i), j, wrap(k)));
      }
  for (int j = 0; j < layers; ++j) c.layer_y.push_back((j + 1) * s);
  const int reach = kGhosts + kWallMargin;
  for (float y : {0.0f, static_cast<float>(kGap)})
    for (int k = -reach; k < kPeriod + reach; ++k)
      for (int i = -reach; i < kPeriod + reach; ++i) c.plates.push_back(Vec3{i * s, y, k * s});
  return c;
}

// Explicit Euler at `step_fraction` of the simulator's viscous step limit
// (CFL mode steps at the limit itself),
// the profile of the core's first column sampled at each of `times`.
std::vector<Profile> start_up(int layers, const std::vector<double>& times, float step_fraction) {
  const Channel c = make_channel(layers);
  CpuExec exec(2);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * c.spacing);
  const UniformGrid grid = test::grid_around({c.liquid, c.plates}, kernel.h);
  const test::SortedSet liquid = test::sort_into(exec, c.liquid, grid);
  const test::SortedSet plates = test::sort_into(exec, c.plates, grid);

  std::vector<float> plate_volume(plates.size());
  exec.parallel_for(plates.size(), ComputeBoundaryVolume{plates.view(), kernel, plate_volume.data()});
  const std::size_t n = liquid.size();
  const std::vector<MassUnits> units(n, kFullParticleUnits);
  const std::vector<float> density(n, static_cast<float>(kDensity));
  const float mass = static_cast<float>(kDensity) * c.spacing * c.spacing * c.spacing;
  // Sorted index of each lattice index, and each sorted particle's source.
  std::vector<std::size_t> sorted_of(n);
  for (std::size_t i = 0; i < n; ++i) sorted_of[liquid.grid.order[i]] = i;
  std::vector<std::size_t> source(n);
  for (std::size_t i = 0; i < n; ++i) source[i] = sorted_of[c.source[liquid.grid.order[i]]];

  std::vector<Vec3> velocity(n), acceleration(n);
  const float limit = viscous_time_step_limit(kernel, static_cast<float>(kNu));
  std::vector<Profile> profiles;
  double t = 0;
  for (double target : times) {
    const int steps = static_cast<int>(std::ceil((target - t) / (step_fraction * limit)));
    const float dt = static_cast<float>((target - t) / steps);
    for (int s = 0; s < steps; ++s) {
      std::fill(acceleration.begin(), acceleration.end(), Vec3{static_cast<float>(kForce), 0, 0});
      exec.parallel_for(n, AddViscosityMorris1997{liquid.view(), plates.view(), units.data(), density.data(),
                                                  plate_volume.data(), velocity.data(), kernel, mass,
                                                  static_cast<float>(kNu),
                                                  wall_layer_volume_per_akinci_volume(kernel, c.spacing),
                                                  acceleration.data()});
      for (std::size_t i = 0; i < n; ++i) velocity[i] += dt * acceleration[i];
      for (std::size_t i = 0; i < n; ++i) velocity[i] = velocity[source[i]];
    }
    t = target;
    Profile p{t, {}};
    for (int j = 0; j < layers; ++j) p.velocity.push_back(velocity[sorted_of[c.index(kGhosts, j, kGhosts)]].x);
    profiles.push_back(p);
  }
  return profiles;
}

// The largest deviation from the analytic profile over every layer and
// sampled time, relative to the steady centre-line speed F L^2 / (8 nu).
double worst_relative_error(int layers, const std::vector<Profile>& profiles) {
  const Channel c = make_channel(layers);
  const double peak = kForce * kGap * kGap / (8 * kNu);
  double worst = 0;
  for (const Profile& p : profiles)
    for (int j = 0; j < layers; ++j)
      worst = std::max(worst, std::fabs(p.velocity[j] - analytic_velocity(c.layer_y[j], p.time)) / peak);
  return worst;
}

// Morris et al.'s sampling times (their Fig. 3) and twice the last, when
// the profile is within 1 % of the steady parabola.
const std::vector<double> kTimes = {0.0225, 0.045, 0.1125, 0.225, 0.45};

class viscosity_Poiseuille : public ::testing::TestWithParam<int> {};

TEST_P(viscosity_Poiseuille, StartUpFollowsTheAnalyticProfileWithin2Percent) {
  const int layers = GetParam();
  const double error = worst_relative_error(layers, start_up(layers, kTimes, 1.0f));
  RecordProperty("worst_relative_error", std::to_string(error));
  EXPECT_LT(error, 0.02) << layers << " layers";
}

INSTANTIATE_TEST_SUITE_P(Resolutions, viscosity_Poiseuille, ::testing::Values(10, 20, 40),
                         [](const ::testing::TestParamInfo<int>& info) { return std::to_string(info.param) + "Layers"; });

// A physical viscosity acts as a rate: the profile does not depend on the
// step (XSPH's smoothing, applied once per step, would).
TEST(viscosity_Poiseuille, ProfileDoesNotDependOnTheTimeStep) {
  const std::vector<double> times = {0.045, 0.225};
  const std::vector<Profile> coarse = start_up(10, times, 1.0f), fine = start_up(10, times, 0.125f);
  const double peak = kForce * kGap * kGap / (8 * kNu);
  for (std::size_t p = 0; p < times.size(); ++p)
    for (std::size_t j = 0; j < coarse[p].velocity.size(); ++j)
      EXPECT_NEAR(coarse[p].velocity[j], fine[p].velocity[j], 2e-3 * peak) << "t = " << times[p] << ", layer " << j;
}

// The wall's liquid-layer volume rests on the cubic spline's integral over
// a plane, 1.4 / h: checked against a quadrature of the kernel itself, and
// on plates sampled at the liquid's spacing and at half of it, where A_b s
// is s^3 and s^3 / 4.
TEST(viscosity_WallLayer, PlaneIntegralAndPlateVolumes) {
  const float s = 0.01f;
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * s);
  double integral = 0;
  const int rings = 20000;
  for (int r = 0; r < rings; ++r) {
    const double rho = (r + 0.5) * kernel.h / rings;
    integral += kernel.W(static_cast<float>(rho)) * 2 * 3.14159265358979323846 * rho * (kernel.h / rings);
  }
  EXPECT_NEAR(wall_layer_volume_per_akinci_volume(kernel, s), s * integral, 1e-4 * s * integral);

  CpuExec exec(0);
  for (float plate_spacing : {s, 0.5f * s}) {
    std::vector<Vec3> plate;
    for (int k = -12; k <= 12; ++k)
      for (int i = -12; i <= 12; ++i) plate.push_back(Vec3{i * plate_spacing, 0, k * plate_spacing});
    const test::SortedSet set = test::sort_into(exec, plate, test::grid_around({plate}, kernel.h));
    std::vector<float> volume(set.size());
    exec.parallel_for(set.size(), ComputeBoundaryVolume{set.view(), kernel, volume.data()});
    const float centre = set.to_lattice(volume)[12 + 25 * 12];
    const double layer = double(plate_spacing) * plate_spacing * s;
    EXPECT_NEAR(wall_layer_volume_per_akinci_volume(kernel, s) * centre, layer, 0.01 * layer) << "plate spacing " << plate_spacing;
  }
}

}  // namespace
}  // namespace dp
