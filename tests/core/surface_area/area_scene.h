#pragma once
// Lattice bodies of liquid, and walls of boundary particles with Akinci
// volumes, sorted into the neighbour grid for the surface area tests.
#include <algorithm>
#include <cmath>
#include <vector>

#include "../sorted_particles.h"
#include "backend/cpu_exec.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/particle_grid.h"
#include "sph/surface_area_orthmann2013.h"

namespace dp::area_test {

using test::grid_around;
using test::sort_into;
using test::SortedSet;

// Akinci 2012, Eq. 4: V_b = 1 / sum_k W_bk over the boundary particles.
inline std::vector<float> akinci_volumes(const SortedSet& wall, const CubicSplineKernel& kernel) {
  std::vector<float> v(wall.size());
  const GridView view = wall.view();
  for (std::size_t b = 0; b < wall.size(); ++b) {
    float sum = 0;
    view.for_each_near(view.position[b], [&](std::uint32_t k) {
      float r2 = length_squared(view.position[b] - view.position[k]);
      if (r2 < kernel.h * kernel.h) sum += kernel.W(std::sqrt(r2));
    });
    v[b] = 1.0f / sum;
  }
  return v;
}

struct Areas {
  std::vector<float> area;  // lattice order, m^2
  double total = 0;
};

// A_i of every liquid particle, optionally next to a wall; all particles of
// weight `weight` at density `density`.
inline Areas surface_areas(const std::vector<Vec3>& liquid, const std::vector<Vec3>& wall, float spacing,
                           int threads = 2, float weight = 1.0f, float density = 1000.0f) {
  CpuExec exec(threads);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * spacing);
  const UniformGrid grid = grid_around({liquid, wall}, kernel.h);
  SortedSet l = sort_into(exec, liquid, grid), w = sort_into(exec, wall, grid);
  std::vector<float> wall_volume = akinci_volumes(w, kernel);
  std::vector<MassUnits> units(liquid.size(), static_cast<MassUnits>(weight * kFullParticleUnits));
  std::vector<float> rho(liquid.size(), density), area(liquid.size());
  const float full_mass = 1000.0f * spacing * spacing * spacing;
  exec.parallel_for(liquid.size(),
                    ComputeSurfaceArea{l.view(), units.data(), rho.data(), full_mass, w.view(), wall_volume.data(),
                                       !wall.empty(), kernel, flat_face_area_calibration(kernel, spacing),
                                       area.data()});
  Areas a;
  a.area = l.to_lattice(area);
  for (float x : a.area) a.total += x;
  return a;
}

// Lattice points within radius n spacings of the origin.
inline std::vector<Vec3> lattice_ball(int n, float spacing) {
  std::vector<Vec3> p;
  for (int k = -n; k <= n; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i)
        if (i * i + j * j + k * k <= n * n) p.push_back(spacing * Vec3{float(i), float(j), float(k)});
  return p;
}

using test::lattice_block;

}  // namespace dp::area_test
