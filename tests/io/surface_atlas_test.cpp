// Surface atlases (paper Sec. 4.3): the texel areas A_t partition the mesh's
// area (reference: the mesh's own triangle areas, summed independently by
// TriangleMesh::area; within 1 %), for a mesh with usable UVs and for meshes
// parameterised by CGAL; texel positions lie on the surface; m_t^max from a
// constant and from an image.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

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

// Writes a width x height image with OpenImageIO (a writer that is not the
// simulator's reader), `channels` channels of `type`, each pixel's channels
// set by value(x, y, c) in [0, 1].
template <class Value>
void write_test_image(const std::filesystem::path& file, int width, int height, int channels, OIIO::TypeDesc type,
                      Value value) {
  std::vector<float> pixels(static_cast<std::size_t>(width) * height * channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c) pixels[(static_cast<std::size_t>(y) * width + x) * channels + c] = value(x, y, c);
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out) << OIIO::geterror();
  OIIO::ImageSpec spec(width, height, channels, type);
  if (channels == 1) spec.channelnames = {"Y"};
  ASSERT_TRUE(out->open(file.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && out->close()) << out->geterror();
}

// An image white on its left half, of any size, over a 100 x 100 atlas: water
// may condense only on the left, away from the edge where the resampling
// filter blends the halves.
void expect_left_half(const std::filesystem::path& image) {
  Built b = build(test::plane_with_uvs("image", 0.3f, 0.2f, 2, 0.0f, 1.0f), 100);
  set_max_mass_from_image(b.raster.texels, image, 0.2);
  const TexelGeometry& g = b.raster.texels;
  int left = 0, right = 0;
  for (std::size_t t = 0; t < g.size(); ++t) {
    const double u = (g.pixel[t] % 100 + 0.5) / 100;
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
}

TEST(MaxMass, FromAnImageOverTheAtlasEnlarged) {
  const auto png = test::test_dir("images") / "half.png";
  write_test_image(png, 64, 32, 3, OIIO::TypeDesc::UINT8, [](int x, int, int) { return x < 32 ? 1.0f : 0.0f; });
  expect_left_half(png);
  Built b = build(test::plane_with_uvs("image", 0.3f, 0.2f, 2, 0.0f, 1.0f), 16);
  EXPECT_THROW(set_max_mass_from_image(b.raster.texels, test::test_dir("images") / "missing.png", 1.0), std::runtime_error);
}

TEST(MaxMass, FromAnImageOverTheAtlasReduced) {
  // Shrinking filters (Mitchell-Netravali) rather than samples, so a thin
  // line of the large image does not vanish or alias.
  const auto png = test::test_dir("images") / "half_large.png";
  write_test_image(png, 400, 300, 1, OIIO::TypeDesc::UINT16, [](int x, int, int) { return x < 200 ? 1.0f : 0.0f; });
  expect_left_half(png);
}

TEST(MaxMass, AnImageAtTheTexturesSizeIsUsedAsItIs) {
  // 16-bit grey PNG and single-channel float EXR: each texel takes its own
  // pixel's value exactly (v / 65535 for the PNG), none of its neighbours'.
  Built b = build(test::plane_with_uvs("image", 0.3f, 0.2f, 2, 0.0f, 1.0f), 100);
  auto value = [](int x, int y, int) { return static_cast<float>(((x * 7 + y * 13) % 100) / 99.0); };
  for (const char* name : {"ramp16.png", "ramp.exr"}) {
    const auto file = test::test_dir("images") / name;
    const bool exr = std::string(name).ends_with(".exr");
    write_test_image(file, 100, 100, 1, exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT16, value);
    set_max_mass_from_image(b.raster.texels, file, 0.5);
    const TexelGeometry& g = b.raster.texels;
    for (std::size_t t = 0; t < g.size(); ++t) {
      const int x = g.pixel[t] % 100, y = g.pixel[t] / 100;
      const double expected = exr ? value(x, y, 0) : std::round(value(x, y, 0) * 65535.0) / 65535.0;
      ASSERT_NEAR(g.max_mass[t], expected * 0.5 * g.area[t], 1e-6 * 0.5 * g.area[t]) << name << " texel " << t;
    }
  }
}

TEST(MaxMass, AnImageThatIsNotOneNamesItsFile) {
  const auto file = test::test_dir("images") / "not_an_image.png";
  std::ofstream(file) << "this is text";
  Built b = build(test::plane_with_uvs("image", 0.3f, 0.2f, 2, 0.0f, 1.0f), 16);
  try {
    set_max_mass_from_image(b.raster.texels, file, 1.0);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dp::io
