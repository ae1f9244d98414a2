// Surface atlases (paper Sec. 4.3): the texel areas A_t partition the mesh's
// area (reference: the mesh's own triangle areas, summed independently by
// TriangleMesh::area; within 1 %), for a mesh with usable UVs and for meshes
// parameterised by CGAL; texel positions lie on the surface; m_t^max from a
// constant and from an image.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "atlas_rasterization.h"
#include "max_mass_texture.h"
#include "surface_atlas.h"
#include "surface_test_meshes.h"
#include "triangle_mesh.h"

namespace dp::io {
namespace {

double texel_area_sum(const TexelGeometry& g) {
  double sum = 0;
  for (float a : g.area) sum += a;
  return sum;
}

struct Built {
  TriangleMesh mesh;
  AtlasMesh atlas;
  AtlasRaster raster;
};

Built build(const std::filesystem::path& file, int resolution) {
  Built b;
  b.mesh = load_triangle_mesh(file);
  b.atlas = make_surface_atlas(b.mesh, resolution, resolution, file.string());
  b.raster = rasterize_atlas(b.atlas, resolution, resolution);
  return b;
}

void expect_unit_normals(const TexelGeometry& g) {
  for (const Vec3& n : g.normal) ASSERT_NEAR(length(n), 1.0f, 1e-5f);
}

TEST(SurfaceAtlas, AssetUvsAreKeptAndTexelAreasSumToTheMeshArea) {
  Built b = build(test::plane_with_uvs("plane", 0.3f, 0.2f, 4, 0.05f, 0.95f), 200);
  EXPECT_EQ(b.atlas.uv_source, "asset");
  const double sum = texel_area_sum(b.raster.texels);
  RecordProperty("relative_area_error", std::to_string(sum / b.mesh.area() - 1));
  EXPECT_NEAR(sum / b.mesh.area(), 1.0, 0.01);
  EXPECT_NEAR(b.mesh.area(), 0.06, 1e-6);
  // UVs cover [0.05, 0.95]^2 of 200^2 texels: 180^2 texels, all fully inside.
  EXPECT_EQ(b.raster.texels.size(), 180u * 180u);
  for (const Vec3& x : b.raster.texels.position) ASSERT_NEAR(x.y, 0.0f, 1e-7f);
  expect_unit_normals(b.raster.texels);
}

TEST(SurfaceAtlas, ACubeWithoutUvsGetsSixGutteredChartsCoveringItsArea) {
  Built b = build(test::cube_without_uvs(), 256);
  EXPECT_EQ(b.atlas.uv_source.rfind("generated", 0), 0u) << b.atlas.uv_source;
  EXPECT_EQ(b.atlas.positions.size(), 24u);  // 6 charts of 4 corners
  const double sum = texel_area_sum(b.raster.texels);
  RecordProperty("relative_area_error", std::to_string(sum / 6.0 - 1));
  EXPECT_NEAR(sum / 6.0, 1.0, 0.01);
  for (const auto& uv : b.atlas.uvs) ASSERT_TRUE(uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1);
  // The gutter keeps every texel on one face: its position on that face,
  // its normal that face's axis.
  for (std::size_t t = 0; t < b.raster.texels.size(); ++t) {
    const Vec3 x = b.raster.texels.position[t], n = b.raster.texels.normal[t];
    ASSERT_NEAR(max_abs_component(x), 0.5f, 1e-5f);
    ASSERT_NEAR(max_abs_component(n), 1.0f, 1e-6f) << "texel " << t << " mixes faces";
    ASSERT_NEAR(dot(n, x), 0.5f, 1e-5f);  // outward
  }
  EXPECT_LE(b.raster.max_coverage, 1 + 1e-6);
  // Six squares in a square atlas: 6/9 of it at best with one row of three.
  const double used = static_cast<double>(b.raster.texels.size()) / (256.0 * 256.0);
  RecordProperty("atlas_fill", std::to_string(used));
  EXPECT_GT(used, 0.5);
}

TEST(SurfaceAtlas, ASphereWithoutUvsIsParameterisedByCgal) {
  Built b = build(test::sphere_without_uvs(3), 512);
  EXPECT_EQ(b.atlas.uv_source.rfind("generated", 0), 0u);
  const double sum = texel_area_sum(b.raster.texels);
  RecordProperty("relative_area_error", std::to_string(sum / b.mesh.area() - 1));
  EXPECT_NEAR(sum / b.mesh.area(), 1.0, 0.01);
  EXPECT_NEAR(b.mesh.area() / (4 * 3.14159265358979), 1.0, 0.02);  // a fine icosphere is nearly the unit sphere
  EXPECT_LE(b.raster.max_coverage, 1 + 1e-6);
  EXPECT_LT(b.raster.lost_area, 1e-9);
  for (std::size_t t = 0; t < b.raster.texels.size(); ++t) {
    const Vec3 x = b.raster.texels.position[t];
    ASSERT_TRUE(length(x) > 0.98f && length(x) < 1.0f + 1e-5f) << length(x);
    ASSERT_GT(dot(b.raster.texels.normal[t], normalize(x)), 0.95f);
  }
  // Charts keep world areas: texels are of nearly one size.
  const double mean = sum / static_cast<double>(b.raster.texels.size());
  int full = 0;
  for (float a : b.raster.texels.area) full += a > 0.5 * mean;
  EXPECT_GT(full, static_cast<int>(0.8 * b.raster.texels.size()));
}

TEST(SurfaceAtlas, ATorusWhoseChartsAreRingsIsCutIntoDiscs) {
  Built b = build(test::torus_without_uvs(1.0, 0.3, 48, 24), 512);
  const double sum = texel_area_sum(b.raster.texels);
  RecordProperty("relative_area_error", std::to_string(sum / b.mesh.area() - 1));
  EXPECT_NEAR(sum / b.mesh.area(), 1.0, 0.01);
  EXPECT_LE(b.raster.max_coverage, 1 + 1e-6);
  EXPECT_LT(b.raster.lost_area, 1e-9);
  // On the torus: distance r from the core circle, up to the facets' sag.
  for (const Vec3& x : b.raster.texels.position) {
    const double ring = std::sqrt(double(x.x) * x.x + double(x.z) * x.z) - 1.0;
    ASSERT_NEAR(std::sqrt(ring * ring + double(x.y) * x.y), 0.3, 0.01);
  }
}

TEST(SurfaceAtlas, OverlappingAssetUvsAreReplaced) {
  Built b = build(test::plane_with_uvs("mirrored", 0.4f, 0.2f, 4, 0.0f, 1.0f, true), 128);
  EXPECT_NE(b.atlas.uv_source.find("overlapping"), std::string::npos) << b.atlas.uv_source;
  EXPECT_NEAR(texel_area_sum(b.raster.texels) / b.mesh.area(), 1.0, 0.01);
}

TEST(SurfaceAtlas, TheDemoTrayWhoseFacesShareUvsGetsItsOwnAtlas) {
  Built b = build(std::filesystem::path(DEWPOINT_SOURCE_DIR) / "assets/meshes/tray.obj", 256);
  EXPECT_NE(b.atlas.uv_source.find("generated"), std::string::npos);
  EXPECT_NEAR(texel_area_sum(b.raster.texels), 0.36 + 4 * 0.6 * 0.2, 0.01 * 0.84);
  const double used = static_cast<double>(b.raster.texels.size()) / (256.0 * 256.0);
  RecordProperty("atlas_fill", std::to_string(used));
  EXPECT_GT(used, 0.5);
}

TEST(MaxMass, ConstantTimesArea) {
  Built b = build(test::plane_with_uvs("constant", 0.3f, 0.2f, 2, 0.0f, 1.0f), 64);
  set_constant_max_mass(b.raster.texels, 0.05);
  double total = 0;
  for (float m : b.raster.texels.max_mass) total += m;
  EXPECT_NEAR(total, 0.05 * 0.06, 1e-6 * 0.003);
}

TEST(MaxMass, FromAnImageOverTheAtlas) {
  // A 64 x 32 PNG, white on its left half: only there may water condense.
  const auto png = test::test_dir("images") / "half.png";
  {
    std::vector<unsigned char> pixels(64 * 32 * 3, 0);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        for (int c = 0; c < 3; ++c) pixels[(y * 64 + x) * 3 + c] = 255;
    auto out = OIIO::ImageOutput::create(png.string());
    ASSERT_TRUE(out && out->open(png.string(), OIIO::ImageSpec(64, 32, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close());
  }
  Built b = build(test::plane_with_uvs("image", 0.3f, 0.2f, 2, 0.0f, 1.0f), 100);
  set_max_mass_from_image(b.raster.texels, png, 0.2);
  const TexelGeometry& g = b.raster.texels;
  int left = 0, right = 0;
  for (std::size_t t = 0; t < g.size(); ++t) {
    const double u = (g.pixel[t] % 100 + 0.5) / 100;
    // Away from the edge, where the resampling filter blends the halves.
    if (u < 0.4) {
      EXPECT_NEAR(g.max_mass[t], 0.2 * g.area[t], 1e-2 * 0.2 * g.area[t]);
      ++left;
    }
    if (u > 0.6) {
      EXPECT_NEAR(g.max_mass[t], 0.0f, 1e-2 * 0.2 * g.area[t]);
      ++right;
    }
  }
  EXPECT_GT(left, 3500);
  EXPECT_GT(right, 3500);
  EXPECT_THROW(set_max_mass_from_image(b.raster.texels, test::test_dir("images") / "missing.png", 1.0), std::runtime_error);
}

}  // namespace
}  // namespace dp::io
