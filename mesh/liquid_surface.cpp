#include "liquid_surface.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "marching_cubes.h"

namespace dp::mesh {

namespace {

void require_positive(double value, const std::string& what) {
  if (!(value > 0) || !std::isfinite(value)) {
    char found[32];
    std::snprintf(found, sizeof found, "%g", value);
    throw std::invalid_argument(what + " must be positive and finite, found " + found);
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SurfaceParameters surface_parameters(double particle_spacing, const io::MeshSettings& settings, double voxel_size,
                                     double voxels_per_radius) {
  require_positive(particle_spacing, "particle spacing");
  SurfaceParameters p;
  p.particle_radius = settings.particle_radius_factor * particle_spacing;
  p.kernel_radius = settings.kernel_radius_factor * particle_spacing;
  const double per_radius = voxels_per_radius > 0 ? voxels_per_radius : settings.voxels_per_radius;
  p.voxel_size = voxel_size > 0 ? voxel_size : p.particle_radius / per_radius;
  require_positive(p.particle_radius, "mesh.particle_radius_factor * particle spacing");
  require_positive(p.kernel_radius, "mesh.kernel_radius_factor * particle spacing");
  require_positive(p.voxel_size, "voxel size");
  return p;
}

LiquidSurface liquid_surface(const LiquidParticles& particles, const SurfaceParameters& parameters,
                             const ContactAngleCorrection_HochstetterKolb2017* correction, ScalarGrid* field_out) {
  LiquidSurface surface;
  if (particles.size() == 0) return surface;
  auto start = std::chrono::steady_clock::now();
  surface.grid = zhu_bridson_grid_box(particles, parameters.kernel_radius, parameters.voxel_size);
  ScalarGrid field = sample_liquid_field(particles, parameters.kernel_radius, surface.grid, correction, &surface.counts);
  surface.field_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  surface.mesh = marching_cubes(field);
  surface.marching_cubes_seconds = seconds_since(start);
  if (field_out) *field_out = std::move(field);
  return surface;
}

}  // namespace dp::mesh
