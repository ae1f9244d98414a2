#pragma once
// From particles to the liquid's surface mesh: the Zhu-Bridson field (paper
// Eq. 19), corrected at rigid walls (Eq. 20-24) when walls are given,
// sampled on a grid, then marching cubes.
#include "liquid_field.h"
#include "liquid_particles.h"
#include "scene.h"
#include "surface_mesh.h"
#include "zhu_bridson.h"

namespace dp::mesh {

struct SurfaceParameters {
  double particle_radius = 0;  // nominal r, for w = 1
  double kernel_radius = 0;    // R of Eq. 19
  double voxel_size = 0;
};

// The scene's mesh settings applied to the frames' particle spacing. A
// voxel_size > 0 wins over voxels_per_radius > 0, which wins over the scene's.
// Throws std::invalid_argument on non-positive results.
SurfaceParameters surface_parameters(double particle_spacing, const io::MeshSettings& settings,
                                     double voxel_size = 0, double voxels_per_radius = 0);

struct LiquidSurface {
  SurfaceMesh mesh;
  GridBox grid;  // the sampling grid; empty when there are no particles
  LiquidFieldCounts counts;
  double field_seconds = 0, marching_cubes_seconds = 0;
};

// `correction` may be null: the uncorrected surface. Where `field` is given,
// it receives the sampled field the mesh contours (for a level set).
LiquidSurface liquid_surface(const LiquidParticles& particles, const SurfaceParameters& parameters,
                             const ContactAngleCorrection_HochstetterKolb2017* correction = nullptr,
                             ScalarGrid* field = nullptr);

}  // namespace dp::mesh
