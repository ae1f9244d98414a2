#include "surface_atlas.h"

#include <sstream>
#include <stdexcept>

#include "atlas_rasterization.h"
#include "chart_parameterization.h"

namespace dp::io {

namespace {

AtlasMesh atlas_from_asset(const TriangleMesh& mesh) {
  AtlasMesh a;
  a.positions = mesh.positions;
  a.normals = mesh.normals;
  a.uvs = mesh.uvs;
  a.triangles = mesh.triangles;
  a.uv_source = "asset";
  return a;
}

// Why the asset's UVs cannot serve as an atlas, or "" when they can. Every
// texel must belong to one place on the surface and every part of the
// surface to some texel.
std::string atlas_problem(const AtlasMesh& atlas, int width, int height) {
  for (const auto& uv : atlas.uvs)
    if (uv[0] < 0 || uv[0] > 1 || uv[1] < 0 || uv[1] > 1) return "UVs outside [0,1]^2";
  const AtlasRaster raster = rasterize_atlas(atlas, width, height);
  std::ostringstream why;
  if (raster.max_coverage > 1 + 1e-4) {
    why << "overlapping UVs (a texel " << raster.max_coverage << " times covered)";
    return why.str();
  }
  if (raster.lost_area > 1e-4 * raster.mesh_area) {
    why << "UV-collapsed triangles (" << 100 * raster.lost_area / raster.mesh_area << " % of the area)";
    return why.str();
  }
  return "";
}

}  // namespace

AtlasMesh make_surface_atlas(const TriangleMesh& mesh, int width, int height, const std::string& mesh_name) {
  std::string reason = "the mesh has no UVs";
  if (!mesh.uvs.empty()) {
    AtlasMesh asset = atlas_from_asset(mesh);
    reason = atlas_problem(asset, width, height);
    if (reason.empty()) return asset;
  }
  AtlasMesh generated = parameterize_charts(mesh, width, height, mesh_name);
  generated.uv_source = "generated (" + reason + ")";
  return generated;
}

}  // namespace dp::io
