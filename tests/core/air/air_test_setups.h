#pragma once
// Air grids built in code for the air phase's tests.
#include <cmath>
#include <cstdio>
#include <string>
#include <random>
#include <vector>

#include "air/air_grid.h"
#include "backend/cpu_exec.h"
#include "sph/particle_grid.h"

namespace dp::test {

// One thread: the suites run beside other builds on two cores, where two
// OpenMP threads wait on each other's time slices at every kernel's barrier;
// thread-count independence is tested on its own (air_determinism_test).
inline CpuExec air_exec() { return CpuExec(1); }

// z = M^-1 r, one V-cycle of the pressure preconditioner laid out as
// `layout`, on backend Exec, for the cells and right-hand side given on the
// host: the multigrid layouts' checks on either backend.
template <class Exec>
std::vector<float> one_v_cycle(const Exec& exec, const int (&n)[3], DomainFaces faces, const CycleLayout& layout,
                               const std::vector<std::uint8_t>& unknown, const std::vector<float>& r) {
  typename Exec::template Buffer<std::uint8_t> cells;
  typename Exec::template Buffer<float> rhs;
  Exec::upload(cells, unknown);
  Exec::upload(rhs, r);
  MultigridPreconditioner<Exec> mg;
  mg.resize(n[0], n[1], n[2], faces);
  mg.set_layout(layout);
  mg.set_unknowns(exec, cells);
  PaddedField<Exec> z;
  mg.apply(exec, rhs, z);
  return z.download();
}

inline std::string sci(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3e", v);
  return s;
}

// A cube [0, L]^3 of n^3 cells, all faces closed, no forces or diffusion.
inline AirSettings quiet_air_box(int n, float length = 1.0f) {
  AirSettings s;
  s.domain_min = Vec3{0, 0, 0};
  s.domain_max = Vec3{length, length, length};
  s.resolution = n;
  s.buoyancy_alpha = 0;
  s.buoyancy_beta = 0;
  s.vapor_diffusivity = 0;
  s.heat_diffusivity = 0;
  s.ambient_vapor = 0;
  return s;
}

// A set of particles sorted into a neighbour grid, as the simulation keeps
// its rigid and liquid particles; `view()` is what the air grid reads.
struct SortedParticles {
  ParticleGrid<CpuExec> grid;
  std::vector<Vec3> position;  // sorted

  SortedParticles(const CpuExec& exec, const std::vector<Vec3>& p, Vec3 lo, Vec3 hi, float cell) {
    grid.grid.origin = lo;
    grid.grid.cell_size = cell;
    grid.grid.nx = static_cast<int>(std::ceil((hi.x - lo.x) / cell)) + 1;
    grid.grid.ny = static_cast<int>(std::ceil((hi.y - lo.y) / cell)) + 1;
    grid.grid.nz = static_cast<int>(std::ceil((hi.z - lo.z) / cell)) + 1;
    grid.sort(exec, p);
    position.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) position[i] = p[grid.order[i]];
    grid.find_ranges(exec);
  }
  GridView view() const { return grid.view(position); }
  ParticlePositions positions() const { return ParticlePositions{position.data(), position.size()}; }
};

// Points on a sphere's surface, about `spacing` apart (Fibonacci lattice).
inline std::vector<Vec3> sphere_shell(Vec3 c, float r, float spacing) {
  const int n = static_cast<int>(4.0f * 3.14159265f * r * r / (spacing * spacing)) + 1;
  std::vector<Vec3> p;
  const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < n; ++i) {
    const float y = 1.0f - 2.0f * (i + 0.5f) / n, rad = std::sqrt(1.0f - y * y), t = golden * i;
    p.push_back(c + r * Vec3{rad * std::cos(t), y, rad * std::sin(t)});
  }
  return p;
}

// Uniform random values in [-a, a] for every face.
inline void randomise_velocity(AirSnapshot& s, float a, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-a, a);
  for (auto* f : {&s.u, &s.v, &s.w})
    for (float& x : *f) x = u(rng);
}

// max over air cells of |net outflow| / max |u|: the relative discrete
// divergence, dx |div u| / max |u|.
inline double relative_divergence(const AirSnapshot& s) {
  double umax = 0, dmax = 0;
  for (auto* f : {&s.u, &s.v, &s.w})
    for (float x : *f) umax = std::fmax(umax, std::fabs(x));
  const MacGrid& g = s.grid;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        if (s.kind[g.cell(i, j, k)] == kAirCell)
          dmax = std::fmax(dmax, std::fabs(net_outflow(g, s.u.data(), s.v.data(), s.w.data(), i, j, k)));
  return umax > 0 ? dmax / umax : 0;
}

}  // namespace dp::test
