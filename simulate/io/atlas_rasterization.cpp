#include "atlas_rasterization.h"

#include <algorithm>
#include <cmath>

namespace dp::io {

namespace {

struct P2 {
  double x, y;
};
struct P3 {
  double x, y, z;
};

P3 operator+(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
P3 operator-(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P3 operator*(double s, P3 a) { return {s * a.x, s * a.y, s * a.z}; }
P3 cross(P3 a, P3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double norm(P3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
double cross2(P2 a, P2 b, P2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// A convex polygon of at most 3 + 4 vertices: a square clipped by a triangle.
struct Polygon {
  P2 v[8];
  int n = 0;
};

// Sutherland-Hodgman: keeps the part left of the directed line a -> b.
Polygon clip(const Polygon& in, P2 a, P2 b) {
  Polygon out;
  for (int i = 0; i < in.n; ++i) {
    const P2 p = in.v[i], q = in.v[(i + 1) % in.n];
    const double sp = cross2(a, b, p), sq = cross2(a, b, q);
    if (sp >= 0) out.v[out.n++] = p;
    if ((sp >= 0) != (sq >= 0)) {
      const double t = sp / (sp - sq);
      out.v[out.n++] = P2{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
    }
  }
  return out;
}

// Area and centroid of a convex polygon (shoelace).
void area_and_centroid(const Polygon& poly, double& area, P2& centroid) {
  double a = 0, cx = 0, cy = 0;
  for (int i = 0; i < poly.n; ++i) {
    const P2 p = poly.v[i], q = poly.v[(i + 1) % poly.n];
    const double c = p.x * q.y - q.x * p.y;
    a += c;
    cx += (p.x + q.x) * c;
    cy += (p.y + q.y) * c;
  }
  area = 0.5 * a;
  centroid = area != 0 ? P2{cx / (6 * area), cy / (6 * area)} : P2{0, 0};
}

// Per-texel sums while triangles are rasterised.
struct Accumulator {
  std::vector<double> area, coverage;
  std::vector<P3> centroid, normal;
  explicit Accumulator(std::size_t n) : area(n, 0), coverage(n, 0), centroid(n, P3{0, 0, 0}), normal(n, P3{0, 0, 0}) {}
};

struct Triangle {
  P2 uv[3];     // texel coordinates: x = s * width, y = (1 - t) * height
  P3 world[3];
  P3 normal;    // unit geometric normal
  double world_per_texel_area;
};

void rasterize_triangle(const Triangle& tri, int width, int height, Accumulator& acc) {
  const double det = cross2(tri.uv[0], tri.uv[1], tri.uv[2]);
  const int c0 = std::max(0, static_cast<int>(std::floor(std::min({tri.uv[0].x, tri.uv[1].x, tri.uv[2].x}))));
  const int c1 = std::min(width - 1, static_cast<int>(std::floor(std::max({tri.uv[0].x, tri.uv[1].x, tri.uv[2].x}))));
  const int r0 = std::max(0, static_cast<int>(std::floor(std::min({tri.uv[0].y, tri.uv[1].y, tri.uv[2].y}))));
  const int r1 = std::min(height - 1, static_cast<int>(std::floor(std::max({tri.uv[0].y, tri.uv[1].y, tri.uv[2].y}))));
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      Polygon poly;
      poly.n = 4;
      poly.v[0] = {double(c), double(r)};
      poly.v[1] = {double(c + 1), double(r)};
      poly.v[2] = {double(c + 1), double(r + 1)};
      poly.v[3] = {double(c), double(r + 1)};
      for (int e = 0; e < 3 && poly.n > 0; ++e) poly = clip(poly, tri.uv[e], tri.uv[(e + 1) % 3]);
      if (poly.n < 3) continue;
      double a;
      P2 centre;
      area_and_centroid(poly, a, centre);
      if (!(a > 0)) continue;
      // Barycentric coordinates of the piece's centroid map it to the world.
      const double l1 = cross2(tri.uv[2], tri.uv[0], centre) / det, l2 = cross2(tri.uv[0], tri.uv[1], centre) / det;
      const P3 x = tri.world[0] + l1 * (tri.world[1] - tri.world[0]) + l2 * (tri.world[2] - tri.world[0]);
      const double world_area = a * tri.world_per_texel_area;
      const std::size_t t = static_cast<std::size_t>(r) * width + c;
      acc.area[t] += world_area;
      acc.coverage[t] += a;
      acc.centroid[t] = acc.centroid[t] + world_area * x;
      acc.normal[t] = acc.normal[t] + world_area * tri.normal;
    }
}

}  // namespace

AtlasRaster rasterize_atlas(const AtlasMesh& atlas, int width, int height) {
  AtlasRaster out;
  Accumulator acc(static_cast<std::size_t>(width) * height);
  for (const auto& f : atlas.triangles) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) {
      const auto& p = atlas.positions[f[k]];
      const auto& uv = atlas.uvs[f[k]];
      tri.world[k] = P3{p[0], p[1], p[2]};
      tri.uv[k] = P2{uv[0] * double(width), (1.0 - uv[1]) * double(height)};
    }
    const P3 n = cross(tri.world[1] - tri.world[0], tri.world[2] - tri.world[0]);
    const double world_area = 0.5 * norm(n);
    out.mesh_area += world_area;
    double texel_area = 0.5 * cross2(tri.uv[0], tri.uv[1], tri.uv[2]);
    if (!(std::fabs(texel_area) > 1e-12) || !(world_area > 0)) {
      out.lost_area += world_area;
      continue;
    }
    tri.normal = (1.0 / norm(n)) * n;
    if (texel_area < 0) {  // clipping wants the triangle counter-clockwise in texel coordinates
      std::swap(tri.uv[1], tri.uv[2]);
      std::swap(tri.world[1], tri.world[2]);
      texel_area = -texel_area;
    }
    tri.world_per_texel_area = world_area / texel_area;
    rasterize_triangle(tri, width, height, acc);
  }

  TexelGeometry& g = out.texels;
  g.width = width;
  g.height = height;
  double rasterized = 0;
  for (std::size_t t = 0; t < acc.area.size(); ++t) {
    if (!(acc.area[t] > 0)) continue;
    out.max_coverage = std::max(out.max_coverage, acc.coverage[t]);
    rasterized += acc.area[t];
    const P3 x = (1.0 / acc.area[t]) * acc.centroid[t];
    const double nn = norm(acc.normal[t]);
    const P3 n = nn > 0 ? (1.0 / nn) * acc.normal[t] : P3{0, 0, 0};
    g.pixel.push_back(static_cast<std::uint32_t>(t));
    g.position.push_back(Vec3{float(x.x), float(x.y), float(x.z)});
    g.normal.push_back(Vec3{float(n.x), float(n.y), float(n.z)});
    g.area.push_back(static_cast<float>(acc.area[t]));
    g.max_mass.push_back(0.0f);
  }
  // Area outside [0,1]^2 was clipped away: count it as lost too.
  out.lost_area = std::max(out.lost_area, out.mesh_area - rasterized);
  return out;
}

}  // namespace dp::io
