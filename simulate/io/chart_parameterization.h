#pragma once
// A UV atlas for a mesh that has none: the mesh is cut into charts by normal
// direction (faces whose normals share their dominant axis and sign, joined
// across edges), each chart is flattened by least-squares conformal maps
// (CGAL::Surface_mesh_parameterization::LSCM_parameterizer_3, Levy et al.
// 2002), scaled to its world area, turned into its smallest bounding box and
// packed into [0,1]^2 on shelves with a gutter of at least two texels, so no
// texel mixes two charts. A chart that is not a topological disk, or whose
// flattening folds, is halved across its longest extent until it is.
#include "surface_atlas.h"

namespace dp::io {

AtlasMesh parameterize_charts(const TriangleMesh& mesh, int width, int height, const std::string& mesh_name);

}  // namespace dp::io
