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

// A pressure Poisson problem for the multigrid's checks: a 40 x 36 x 33
// grid (levels of 47520, 6120, 810 and 125 cells), one cell in ten a wall,
// the y max face open, and a random right-hand side on the unknowns.
struct PoissonProblem {
  int n[3] = {40, 36, 33};
  DomainFaces faces;
  std::vector<std::uint8_t> unknown;
  std::vector<float> r;
  std::size_t cells() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
};

inline PoissonProblem random_poisson_problem(unsigned seed) {
  PoissonProblem p;
  p.faces.open_mask = 1u << 3;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  p.unknown.resize(p.cells());
  for (auto& c : p.unknown) c = u(rng) > -0.8f;
  p.r.resize(p.cells());
  for (std::size_t c = 0; c < p.cells(); ++c) p.r[c] = p.unknown[c] ? u(rng) : 0.0f;
  return p;
}

// z = M^-1 r, one V-cycle of the pressure preconditioner laid out as
// `layout`, on backend Exec: the multigrid layouts' checks on either
// backend.
template <class Exec>
std::vector<float> one_v_cycle(const Exec& exec, const PoissonProblem& p, const CycleLayout& layout) {
  typename Exec::template Buffer<std::uint8_t> cells;
  typename Exec::template Buffer<float> rhs;
  Exec::upload(cells, p.unknown);
  Exec::upload(rhs, p.r);
  MultigridPreconditioner<Exec> mg;
  mg.resize(p.n[0], p.n[1], p.n[2], p.faces);
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
