#pragma once
// A small weakly compressible SPH driver for the surface tension tests, kept
// apart from the simulator's own step so that these tests exercise only
// ComputeSurfaceNormal and ComputeSurfaceTensionAcceleration on top of
// textbook parts: density with per-particle masses and Akinci 2012 boundary
// particles, a linear equation of state clamped at zero, symmetric pressure
// forces, Monaghan artificial viscosity, symplectic Euler. The boundary has
// no friction, so that whatever holds liquid to it is adhesion.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "backend/cpu_exec.h"
#include "sph/mass_units.h"
#include "sph/boundary_akinci2012.h"
#include "sph/particle_grid.h"
#include "sph/surface_tension_akinci2013.h"

namespace dp::test {

struct MiniSphParameters {
  float spacing = 0.01f;         // m
  float rest_density = 1000.0f;  // kg/m^3
  float speed_of_sound = 10.0f;  // m/s; p = c^2 (rho - rho0)
  float viscosity_alpha = 0.1f;
  float tension = 0.0f;          // gamma
  Vec3 gravity{};

  float support_radius() const { return 2.0f * spacing; }
  float particle_mass() const { return rest_density * spacing * spacing * spacing; }
  // CFL 0.4 on the smoothing length h/2.
  float time_step() const { return 0.4f * 0.5f * support_radius() / speed_of_sound; }
};

// rho_i = sum_j m_j W_ij + sum_b rho0 V_b W_ib and p_i = c^2 (rho_i - rho0), at least 0.
struct MiniDensityAndPressure {
  GridView liquid, rigid;
  const MassUnits* units;
  const float* rigid_volume;
  CubicSplineKernel kernel;
  float particle_mass, rest_density, c2;
  float* density;
  float* pressure;
  void operator()(std::size_t i) const {
    const Vec3 xi = liquid.position[i];
    const float h2 = kernel.h * kernel.h;
    float rho = 0.0f;
    liquid.for_each_near(xi, [&](std::uint32_t j) {
      float r2 = length_squared(xi - liquid.position[j]);
      if (r2 < h2) rho += particle_mass * weight_of(units[j]) * kernel.W(sqrtf(r2));
    });
    rigid.for_each_near(xi, [&](std::uint32_t b) {
      float r2 = length_squared(xi - rigid.position[b]);
      if (r2 < h2) rho += rest_density * rigid_volume[b] * kernel.W(sqrtf(r2));
    });
    density[i] = rho;
    pressure[i] = std::max(0.0f, c2 * (rho - rest_density));
  }
};

// Monaghan's artificial viscosity term Pi_ij, zero for separating pairs.
inline float artificial_viscosity(Vec3 xij, Vec3 vij, float alpha, float smoothing_length, float c,
                                  float mean_density) {
  float vx = dot(vij, xij);
  if (vx >= 0.0f) return 0.0f;
  float nu = 2.0f * alpha * smoothing_length * c / mean_density;
  return -nu * vx / (dot(xij, xij) + 0.01f * smoothing_length * smoothing_length);
}

// Pressure (symmetric), artificial viscosity and gravity, plus the surface
// tension contribution computed beforehand; boundary particles push with
// Psi_b p_i / rho_i^2 (Akinci 2012).
struct MiniAcceleration {
  GridView liquid, rigid;
  const MassUnits* units;
  const Vec3* velocity;
  const float* density;
  const float* pressure;
  const float* rigid_volume;
  const Vec3* tension;
  CubicSplineKernel kernel;
  float particle_mass, rest_density, viscosity_alpha, speed_of_sound;
  Vec3 gravity;
  Vec3* acceleration;
  void operator()(std::size_t i) const {
    const Vec3 xi = liquid.position[i], vi = velocity[i];
    const float h2 = kernel.h * kernel.h, hs = 0.5f * kernel.h;
    const float pi_rho2 = pressure[i] / (density[i] * density[i]);
    Vec3 a = gravity + tension[i];
    liquid.for_each_near(xi, [&](std::uint32_t j) {
      Vec3 xij = xi - liquid.position[j];
      if (j == i || length_squared(xij) >= h2) return;
      float mj = particle_mass * weight_of(units[j]);
      float pj_rho2 = pressure[j] / (density[j] * density[j]);
      float visc = artificial_viscosity(xij, vi - velocity[j], viscosity_alpha, hs, speed_of_sound,
                                        0.5f * (density[i] + density[j]));
      a -= (mj * (pi_rho2 + pj_rho2 + visc)) * kernel.gradW(xij);
    });
    rigid.for_each_near(xi, [&](std::uint32_t b) {
      Vec3 xib = xi - rigid.position[b];
      if (length_squared(xib) >= h2) return;
      a -= (rest_density * rigid_volume[b] * pi_rho2) * kernel.gradW(xib);
    });
    acceleration[i] = a;
  }
};

struct MiniSymplecticEuler {
  const Vec3* acceleration;
  float dt;
  Vec3* velocity;
  Vec3* position;
  void operator()(std::size_t i) const {
    velocity[i] += dt * acceleration[i];
    position[i] += dt * velocity[i];
  }
};

// Liquid particles, reordered by grid cell every step, and static boundary
// particles with per-particle adhesion coefficients. One thread by default:
// ctest runs suites side by side, and on a busy machine OpenMP teams spend
// their time waiting for each other at every kernel's barrier.
class MiniSph {
 public:
  MiniSph(const MiniSphParameters& p, Vec3 domain_min, Vec3 domain_max, int threads = 1)
      : p_(p), exec_(threads), kernel_(CubicSplineKernel::with_support(p.support_radius())) {
    const float h = p.support_radius();
    UniformGrid grid;
    grid.origin = domain_min;
    grid.cell_size = h;
    grid.nx = std::max(1, static_cast<int>((domain_max.x - domain_min.x) / h) + 1);
    grid.ny = std::max(1, static_cast<int>((domain_max.y - domain_min.y) / h) + 1);
    grid.nz = std::max(1, static_cast<int>((domain_max.z - domain_min.z) / h) + 1);
    liquid_grid_.grid = grid;
    rigid_grid_.grid = grid;
    set_rigid({}, 0.0f);
  }

  void add_liquid(Vec3 x, MassUnits units = kFullParticleUnits) {
    position.push_back(x);
    velocity.push_back(Vec3{});
    this->units.push_back(units);
  }

  // Boundary particles; their volumes follow Akinci 2012, Eq. 4.
  void set_rigid(const std::vector<Vec3>& points, float adhesion) {
    std::vector<Vec3> unsorted = points;
    rigid_grid_.sort(exec_, unsorted);
    rigid_position_.resize(points.size());
    exec_.parallel_for(points.size(), Gather<Vec3>{rigid_grid_.order.data(), unsorted.data(), rigid_position_.data()});
    rigid_grid_.find_ranges(exec_);
    rigid_volume_.assign(points.size(), 0.0f);
    rigid_adhesion_.assign(points.size(), adhesion);
    exec_.parallel_for(points.size(),
                       ComputeBoundaryVolume{rigid_grid_.view(rigid_position_), kernel_, rigid_volume_.data()});
  }

  // Reorders the liquid by cell and computes density, pressure, normals and
  // the surface tension acceleration for the current positions.
  void evaluate_surface_tension() {
    sort_liquid();
    const std::size_t n = position.size();
    density.resize(n);
    pressure.resize(n);
    normal.resize(n);
    tension.resize(n);
    GridView liquid = liquid_grid_.view(position), rigid = rigid_grid_.view(rigid_position_);
    exec_.parallel_for(n, MiniDensityAndPressure{liquid, rigid, units.data(), rigid_volume_.data(), kernel_,
                                                 p_.particle_mass(), p_.rest_density,
                                                 p_.speed_of_sound * p_.speed_of_sound, density.data(),
                                                 pressure.data()});
    exec_.parallel_for(n, ComputeSurfaceNormal{liquid, units.data(), density.data(), kernel_, p_.particle_mass(),
                                               normal.data()});
    SurfaceTensionParameters st{kernel_, p_.particle_mass(), p_.rest_density, p_.tension};
    exec_.parallel_for(n, ComputeSurfaceTensionAcceleration{liquid, rigid, units.data(), density.data(),
                                                            normal.data(), rigid_volume_.data(),
                                                            rigid_adhesion_.data(), st, tension.data()});
  }

  void step(float dt) {
    evaluate_surface_tension();
    const std::size_t n = position.size();
    acceleration.resize(n);
    GridView liquid = liquid_grid_.view(position), rigid = rigid_grid_.view(rigid_position_);
    exec_.parallel_for(n, MiniAcceleration{liquid, rigid, units.data(), velocity.data(), density.data(),
                                           pressure.data(), rigid_volume_.data(), tension.data(), kernel_,
                                           p_.particle_mass(), p_.rest_density, p_.viscosity_alpha,
                                           p_.speed_of_sound, p_.gravity, acceleration.data()});
    exec_.parallel_for(n, MiniSymplecticEuler{acceleration.data(), dt, velocity.data(), position.data()});
    time += dt;
  }

  double kinetic_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < position.size(); ++i)
      e += 0.5 * p_.particle_mass() * weight_of(units[i]) * length_squared(velocity[i]);
    return e;
  }

  Vec3 centre_of_mass() const {
    double s[3] = {0, 0, 0}, w = 0;
    for (std::size_t i = 0; i < position.size(); ++i) {
      double m = weight_of(units[i]);
      for (int k = 0; k < 3; ++k) s[k] += m * position[i][k];
      w += m;
    }
    return Vec3{static_cast<float>(s[0] / w), static_cast<float>(s[1] / w), static_cast<float>(s[2] / w)};
  }

  const MiniSphParameters& parameters() const { return p_; }

  // Liquid state, in the current (cell) order.
  std::vector<Vec3> position, velocity, normal, tension, acceleration;
  std::vector<MassUnits> units;
  std::vector<float> density, pressure;
  double time = 0.0;

 private:
  void sort_liquid() {
    const std::size_t n = position.size();
    liquid_grid_.sort(exec_, position);
    std::vector<Vec3> x(n), v(n);
    std::vector<MassUnits> u(n);
    const std::uint32_t* order = liquid_grid_.order.data();
    exec_.parallel_for(n, Gather<Vec3>{order, position.data(), x.data()});
    exec_.parallel_for(n, Gather<Vec3>{order, velocity.data(), v.data()});
    exec_.parallel_for(n, Gather<MassUnits>{order, units.data(), u.data()});
    position.swap(x);
    velocity.swap(v);
    units.swap(u);
    liquid_grid_.find_ranges(exec_);
  }

  MiniSphParameters p_;
  CpuExec exec_;
  CubicSplineKernel kernel_;
  ParticleGrid<CpuExec> liquid_grid_, rigid_grid_;
  std::vector<Vec3> rigid_position_;
  std::vector<float> rigid_volume_, rigid_adhesion_;
};

}  // namespace dp::test
