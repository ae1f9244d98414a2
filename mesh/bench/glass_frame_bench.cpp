// A Glass-sized frame (paper Table 1: 174K liquid particles, here at rest in
// a glass) meshed with and without the wall corrections, and by OpenVDB's
// Zhu-Bridson rasterisation + volumeToMesh on the same particles, for
// docs/benchmarks.md. The glass is a thick-walled cylinder of ~100K
// triangles, like the large rigid meshes the paper blames for its 70 %
// correction overhead.
#include <CLI/CLI.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointRasterizeSDF.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <vector>

#include "liquid_surface.h"
#include "mesh_measures.h"

namespace {

using dp::mesh::Vec3d;

// CPU seconds of the whole process (all threads): on a shared machine the
// wall clock also counts other programs' time slices, this does not.
double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Inner wall radius `inner`, outer `outer`, floor from y = -bottom to 0
// (inside), rim at `height`; `segments` around, `rings` up each wall.
dp::io::TriangleMesh glass_mesh(double inner, double outer, double bottom, double height, int segments, int rings) {
  dp::io::TriangleMesh m;
  auto add = [&](double radius, double y, int s) {
    const double a = 2 * M_PI * s / segments;
    m.positions.push_back({float(radius * std::cos(a)), float(y), float(radius * std::sin(a))});
    return std::uint32_t(m.positions.size() - 1);
  };
  // A wall as a grid of quads between radius r at heights y0..y1; `outward` picks the winding.
  auto wall = [&](double r, double y0, double y1, bool outward) {
    const std::uint32_t base = std::uint32_t(m.positions.size());
    for (int k = 0; k <= rings; ++k)
      for (int s = 0; s < segments; ++s) add(r, y0 + (y1 - y0) * k / rings, s);
    for (int k = 0; k < rings; ++k)
      for (int s = 0; s < segments; ++s) {
        const std::uint32_t a = base + k * segments + s, b = base + k * segments + (s + 1) % segments;
        const std::uint32_t c = a + segments, d = b + segments;
        if (outward) m.triangles.push_back({a, c, b}), m.triangles.push_back({b, c, d});
        else m.triangles.push_back({a, b, c}), m.triangles.push_back({b, d, c});
      }
  };
  auto disc = [&](double r, double y, bool up) {
    const std::uint32_t centre = std::uint32_t(m.positions.size());
    m.positions.push_back({0, float(y), 0});
    const std::uint32_t base = std::uint32_t(m.positions.size());
    for (int s = 0; s < segments; ++s) add(r, y, s);
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = base + s, b = base + (s + 1) % segments;
      if (up) m.triangles.push_back({centre, b, a});
      else m.triangles.push_back({centre, a, b});
    }
  };
  wall(outer, -bottom, height, true);
  wall(inner, 0, height, false);
  disc(inner, 0, true);          // the inside floor, facing up
  disc(outer, -bottom, false);   // the foot, facing down
  m.normals.assign(m.positions.size(), {0, 1, 0});
  return m;
}

// A lattice of spacing s filling the glass to `count` particles; the outer
// particles sit `gap` from the wall and the floor (closer than a radius, so
// the corrections reach them).
dp::mesh::LiquidParticles glass_liquid(double inner, double s, double gap, std::size_t count) {
  dp::mesh::LiquidParticles p;
  const int n = int(std::floor((inner - gap) / s));
  for (int layer = 0; p.size() < count; ++layer)
    for (int k = -n; k <= n && p.size() < count; ++k)
      for (int i = -n; i <= n && p.size() < count; ++i) {
        const Vec3d x{i * s, gap + layer * s, k * s};
        if (std::hypot(x.x, x.z) > inner - gap) continue;
        p.position.push_back(x);
        p.radius.push_back(0.5 * s);
        p.velocity.push_back({});
      }
  return p;
}

double openvdb_seconds(const dp::mesh::LiquidParticles& p, double radius, double kernel_radius, double voxel,
                       std::size_t& triangles) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<openvdb::Vec3R> positions;
  for (const Vec3d& x : p.position) positions.emplace_back(x.x, x.y, x.z);
  const openvdb::points::PointAttributeVector<openvdb::Vec3R> wrapper(positions);
  const auto point_transform = openvdb::math::Transform::createLinearTransform(kernel_radius);
  const auto index = openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(wrapper, *point_transform);
  const auto points = openvdb::points::createPointDataGrid<openvdb::points::NullCodec, openvdb::points::PointDataGrid>(
      *index, wrapper, *point_transform);
  const auto sdf = openvdb::points::rasterizeSmoothSpheres(*points, radius, kernel_radius, 3.0,
                                                            openvdb::math::Transform::createLinearTransform(voxel));
  std::vector<openvdb::Vec3s> vertices;
  std::vector<openvdb::Vec3I> tris;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*sdf, vertices, tris, quads, 0.0);
  triangles = tris.size() + 2 * quads.size();
  return seconds_since(start);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dewpoint-bench-mesh-glass: one Glass-sized frame, corrected, plain and through OpenVDB"};
  std::size_t particles = 174000;
  double spacing = 0.001, voxels_per_radius = 2, gap_factor = 0.4;
  int threads = 0, repeats = 3;
  app.add_option("--particles", particles, "liquid particles");
  app.add_option("--spacing", spacing, "particle spacing in metres (radius = spacing / 2, R = 2 spacing)");
  app.add_option("--voxels-per-radius", voxels_per_radius, "voxel size = radius / this (2: the paper's r/2)");
  app.add_option("--threads", threads, "CPU threads (0: all)");
  app.add_option("--repeats", repeats, "timed runs of each variant (the median is reported)");
  CLI11_PARSE(app, argc, argv);
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  openvdb::initialize();

  const double radius = 0.5 * spacing, inner = 30 * spacing;
  const dp::mesh::LiquidParticles liquid = glass_liquid(inner, spacing, gap_factor * spacing, particles);
  const double top = liquid.position.back().y;
  auto start = std::chrono::steady_clock::now();
  const dp::mesh::RigidWalls walls({glass_mesh(inner, inner + 2e-3, 3e-3, top * 1.3, 360, 64)});
  const double bvh_seconds = seconds_since(start);
  dp::mesh::DynamicContactAngleParameters angle{60 * M_PI / 180, 20 * M_PI / 180, 20 * M_PI / 180};
  const dp::mesh::ContactAngleCorrection_HochstetterKolb2017 correction(walls, {{angle}, 1.0});
  const dp::mesh::SurfaceParameters parameters{radius, 2 * spacing, radius / voxels_per_radius};

  std::vector<double> plain, corrected, plain_field, corrected_field, vdb, plain_cpu, corrected_cpu, vdb_cpu;
  dp::mesh::LiquidSurface last_plain, last_corrected;
  std::size_t vdb_triangles = 0;
  for (int r = 0; r < repeats; ++r) {
    double cpu = cpu_seconds();
    start = std::chrono::steady_clock::now();
    last_plain = dp::mesh::liquid_surface(liquid, parameters, nullptr);
    plain.push_back(seconds_since(start));
    plain_cpu.push_back(cpu_seconds() - cpu);
    cpu = cpu_seconds();
    plain_field.push_back(last_plain.field_seconds);
    start = std::chrono::steady_clock::now();
    last_corrected = dp::mesh::liquid_surface(liquid, parameters, &correction);
    corrected.push_back(seconds_since(start));
    corrected_cpu.push_back(cpu_seconds() - cpu);
    cpu = cpu_seconds();
    corrected_field.push_back(last_corrected.field_seconds);
    vdb.push_back(openvdb_seconds(liquid, radius, parameters.kernel_radius, parameters.voxel_size, vdb_triangles));
    vdb_cpu.push_back(cpu_seconds() - cpu);
  }
  const auto& n = last_plain.grid.nodes;
  const auto& c = last_corrected.counts;
  std::printf("particles %zu, spacing %g m, voxel %g m, grid %dx%dx%d, blocks %zu active of %zu, %zu near walls\n",
              liquid.size(), spacing, parameters.voxel_size, n[0], n[1], n[2], c.active_blocks, c.blocks, c.blocks_near_walls);
  std::printf("glass: %zu triangles, BVH %.3f s; corrected nodes %zu of %zu in band, %zu wall queries\n",
              std::size_t(2 * 360 * 64 * 2 + 2 * 360), bvh_seconds, c.correction.corrected, c.correction.considered,
              c.correction.wall_queries);
  std::printf("plain:     %.3f s per frame (field %.3f s, CPU %.3f s), %zu triangles, volume %.7g m^3\n",
              median(plain), median(plain_field), median(plain_cpu), last_plain.mesh.triangles.size(), dp::mesh::enclosed_volume(last_plain.mesh));
  std::printf(
      "corrected: %.3f s per frame (field %.3f s, CPU %.3f s), %zu triangles, volume %.7g m^3, overhead %+.1f %% "
      "(CPU %+.1f %%)\n",
      median(corrected), median(corrected_field), median(corrected_cpu), last_corrected.mesh.triangles.size(),
      dp::mesh::enclosed_volume(last_corrected.mesh), 100 * (median(corrected) / median(plain) - 1),
      100 * (median(corrected_cpu) / median(plain_cpu) - 1));
  std::printf(
      "OpenVDB rasterizeSmoothSpheres + volumeToMesh: %.3f s (CPU %.3f s), %zu triangles; plain / OpenVDB = %.2f "
      "(CPU %.2f)\n",
      median(vdb), median(vdb_cpu), vdb_triangles, median(plain) / median(vdb), median(plain_cpu) / median(vdb_cpu));
  return 0;
}
