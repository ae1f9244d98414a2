#include "chart_parameterization.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

namespace dp::io {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using ChartMesh = CGAL::Surface_mesh<Point3>;
using VertexIndex = ChartMesh::Vertex_index;

struct V2 {
  double x = 0, y = 0;
};

// A flattened chart: its faces (mesh triangle indices), the welded vertices
// it uses and their UVs, in world-area units before packing.
struct Chart {
  std::vector<std::uint32_t> faces;
  std::vector<std::uint32_t> vertices;  // welded ids
  std::vector<V2> uv;                   // per entry of `vertices`
  std::vector<std::array<std::uint32_t, 3>> local;  // per face, indices into `vertices`
  V2 size, offset;
};

// The mesh with vertices welded by position (a mesh stored with split
// normals would otherwise fall apart into single triangles) and its faces'
// edge neighbours across manifold edges.
struct WeldedMesh {
  std::vector<std::array<double, 3>> position;  // per welded vertex
  std::vector<std::uint32_t> source;            // a mesh vertex of each welded vertex
  std::vector<std::array<std::uint32_t, 3>> face;
  std::vector<std::array<double, 3>> normal;    // unit geometric face normal
  std::vector<double> area;
  std::vector<std::vector<std::uint32_t>> neighbours;
};

WeldedMesh weld(const TriangleMesh& mesh) {
  WeldedMesh w;
  std::map<std::array<float, 3>, std::uint32_t> id_of;
  std::vector<std::uint32_t> welded(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    auto [it, fresh] = id_of.emplace(mesh.positions[v], static_cast<std::uint32_t>(w.position.size()));
    if (fresh) {
      w.position.push_back({mesh.positions[v][0], mesh.positions[v][1], mesh.positions[v][2]});
      w.source.push_back(static_cast<std::uint32_t>(v));
    }
    welded[v] = it->second;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces_of_edge;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::array<std::uint32_t, 3> t{welded[mesh.triangles[f][0]], welded[mesh.triangles[f][1]], welded[mesh.triangles[f][2]]};
    w.face.push_back(t);
    const auto &a = w.position[t[0]], &b = w.position[t[1]], &c = w.position[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    w.area.push_back(0.5 * len);
    w.normal.push_back(len > 0 ? std::array<double, 3>{n[0] / len, n[1] / len, n[2] / len} : std::array<double, 3>{0, 0, 0});
    for (int e = 0; e < 3; ++e) {
      std::uint32_t p = t[e], q = t[(e + 1) % 3];
      faces_of_edge[{std::min(p, q), std::max(p, q)}].push_back(static_cast<std::uint32_t>(f));
    }
  }
  w.neighbours.resize(w.face.size());
  for (const auto& [edge, faces] : faces_of_edge)
    if (faces.size() == 2) {
      w.neighbours[faces[0]].push_back(faces[1]);
      w.neighbours[faces[1]].push_back(faces[0]);
    }
  return w;
}

// Which of +x, -x, +y, -y, +z, -z a face mostly looks towards.
int normal_class(const std::array<double, 3>& n) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(n[a]) > std::fabs(n[axis])) axis = a;
  return 2 * axis + (n[axis] < 0 ? 1 : 0);
}

// Edge-connected groups of `faces` whose members satisfy same(f, g).
template <class Same>
std::vector<std::vector<std::uint32_t>> connected_groups(const WeldedMesh& w, const std::vector<std::uint32_t>& faces,
                                                         const Same& same) {
  std::map<std::uint32_t, int> group;
  for (std::uint32_t f : faces) group[f] = -1;
  std::vector<std::vector<std::uint32_t>> groups;
  for (std::uint32_t start : faces) {
    if (group[start] >= 0) continue;
    const int id = static_cast<int>(groups.size());
    groups.emplace_back();
    std::vector<std::uint32_t> stack{start};
    group[start] = id;
    while (!stack.empty()) {
      std::uint32_t f = stack.back();
      stack.pop_back();
      groups[id].push_back(f);
      for (std::uint32_t g : w.neighbours[f]) {
        auto it = group.find(g);
        if (it != group.end() && it->second < 0 && same(f, g)) {
          it->second = id;
          stack.push_back(g);
        }
      }
    }
    std::sort(groups[id].begin(), groups[id].end());
  }
  return groups;
}

void index_vertices(const WeldedMesh& w, Chart& chart) {
  std::map<std::uint32_t, std::uint32_t> local_of;
  for (std::uint32_t f : chart.faces) {
    std::array<std::uint32_t, 3> l;
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = local_of.emplace(w.face[f][k], static_cast<std::uint32_t>(chart.vertices.size()));
      if (fresh) chart.vertices.push_back(w.face[f][k]);
      l[k] = it->second;
    }
    chart.local.push_back(l);
  }
  chart.uv.assign(chart.vertices.size(), V2{});
}

double signed_uv_area(const Chart& c, std::size_t f) {
  const V2 a = c.uv[c.local[f][0]], b = c.uv[c.local[f][1]], d = c.uv[c.local[f][2]];
  return 0.5 * ((b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x));
}

// A single triangle laid flat with its true edge lengths.
bool flatten_triangle(const WeldedMesh& w, Chart& chart) {
  const auto& t = w.face[chart.faces[0]];
  auto d = [&](int i, int j) {
    double s = 0;
    for (int a = 0; a < 3; ++a) s += (w.position[t[j]][a] - w.position[t[i]][a]) * (w.position[t[j]][a] - w.position[t[i]][a]);
    return std::sqrt(s);
  };
  const double ab = d(0, 1), ac = d(0, 2), bc = d(1, 2);
  if (!(ab > 0)) return false;
  const double x = (ab * ab + ac * ac - bc * bc) / (2 * ab);
  chart.uv[0] = {0, 0};
  chart.uv[1] = {ab, 0};
  chart.uv[2] = {x, std::sqrt(std::max(0.0, ac * ac - x * x))};
  return true;
}

// LSCM needs a topological disk: one border cycle and Euler characteristic 1.
bool is_disk(const ChartMesh& m) {
  std::size_t cycles = 0;
  std::vector<bool> seen(m.number_of_halfedges(), false);
  for (auto h : m.halfedges()) {
    if (!m.is_border(h) || seen[h]) continue;
    ++cycles;
    for (auto g = h; !seen[g]; g = m.next(g)) seen[g] = true;
  }
  const long euler = static_cast<long>(m.number_of_vertices()) - static_cast<long>(m.number_of_edges()) +
                     static_cast<long>(m.number_of_faces());
  return cycles == 1 && euler == 1;
}

bool flatten_lscm(const WeldedMesh& w, Chart& chart) {
  ChartMesh m;
  std::vector<VertexIndex> vertex;
  for (std::uint32_t v : chart.vertices) vertex.push_back(m.add_vertex(Point3(w.position[v][0], w.position[v][1], w.position[v][2])));
  for (const auto& l : chart.local)
    if (m.add_face(vertex[l[0]], vertex[l[1]], vertex[l[2]]) == ChartMesh::null_face()) return false;  // non-manifold
  if (!is_disk(m)) return false;
  ChartMesh::Halfedge_index border;
  for (auto h : m.halfedges())
    if (m.is_border(h)) {
      border = h;
      break;
    }
  auto uv = m.add_property_map<VertexIndex, Point2>("v:uv").first;
  if (SMP::parameterize(m, SMP::LSCM_parameterizer_3<ChartMesh>(), border, uv) != SMP::OK) return false;
  for (std::size_t i = 0; i < vertex.size(); ++i) chart.uv[i] = {uv[vertex[i]].x(), uv[vertex[i]].y()};
  return true;
}

// The flattening must keep every triangle's orientation (no folds); a
// mirrored result is flipped back.
bool orientation_kept(const WeldedMesh& w, Chart& chart) {
  double total = 0;
  for (std::size_t f = 0; f < chart.faces.size(); ++f) total += signed_uv_area(chart, f);
  if (total < 0)
    for (V2& p : chart.uv) p.x = -p.x;
  double chart_area = 0;
  for (std::uint32_t f : chart.faces) chart_area += w.area[f];
  for (std::size_t f = 0; f < chart.faces.size(); ++f)
    if (w.area[chart.faces[f]] > 1e-9 * chart_area && !(signed_uv_area(chart, f) > 0)) return false;
  return std::isfinite(total) && total != 0;
}

// Halves a chart across the longest extent of its face centroids.
std::array<std::vector<std::uint32_t>, 2> halve(const WeldedMesh& w, const std::vector<std::uint32_t>& faces) {
  auto centroid = [&](std::uint32_t f, int a) {
    return (w.position[w.face[f][0]][a] + w.position[w.face[f][1]][a] + w.position[w.face[f][2]][a]) / 3;
  };
  int axis = 0;
  double best = -1, mid = 0;
  for (int a = 0; a < 3; ++a) {
    double lo = 1e300, hi = -1e300;
    for (std::uint32_t f : faces) lo = std::min(lo, centroid(f, a)), hi = std::max(hi, centroid(f, a));
    if (hi - lo > best) best = hi - lo, axis = a, mid = 0.5 * (lo + hi);
  }
  std::array<std::vector<std::uint32_t>, 2> parts;
  for (std::uint32_t f : faces) parts[centroid(f, axis) < mid ? 0 : 1].push_back(f);
  if (parts[0].empty() || parts[1].empty()) {  // coincident centroids: split by count
    parts[0].assign(faces.begin(), faces.begin() + faces.size() / 2);
    parts[1].assign(faces.begin() + faces.size() / 2, faces.end());
  }
  return parts;
}

void flatten(const WeldedMesh& w, const std::vector<std::uint32_t>& faces, std::vector<Chart>& charts) {
  Chart chart;
  chart.faces = faces;
  index_vertices(w, chart);
  const bool flat = faces.size() == 1 ? flatten_triangle(w, chart) : flatten_lscm(w, chart);
  if (flat && orientation_kept(w, chart)) {
    charts.push_back(std::move(chart));
    return;
  }
  if (faces.size() == 1) return;  // a degenerate triangle: no area to texture
  for (const auto& part : halve(w, faces))
    for (const auto& group : connected_groups(w, part, [](std::uint32_t, std::uint32_t) { return true; }))
      flatten(w, group, charts);
}

// Convex hull of points (Andrew's monotone chain), counter-clockwise.
std::vector<V2> convex_hull(std::vector<V2> p) {
  std::sort(p.begin(), p.end(), [](V2 a, V2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  auto turn = [](V2 o, V2 a, V2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<V2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && turn(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// The direction of the chart's smallest-area bounding box: one of its
// sides lies along an edge of the convex hull (Freeman & Shapira 1975).
double box_angle(const std::vector<V2>& uv) {
  const std::vector<V2> hull = convex_hull(uv);
  double best_area = 1e300, best_angle = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const V2 a = hull[i], b = hull[(i + 1) % hull.size()];
    const double angle = std::atan2(b.y - a.y, b.x - a.x), cs = std::cos(angle), sn = std::sin(angle);
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const V2& p : hull) {
      const double x = cs * p.x + sn * p.y, y = -sn * p.x + cs * p.y;
      lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
    }
    const double area = (hi_x - lo_x) * (hi_y - lo_y);
    if (area < best_area * (1 - 1e-9)) best_area = area, best_angle = angle;
  }
  return best_angle;
}

// Scales a chart so UV area equals world area (every chart gets the same
// texel density), turns it into its smallest bounding box, lying flat, and
// moves it to the origin. Rotations keep the orientation.
void normalise(const WeldedMesh& w, Chart& c) {
  double uv_area = 0, world_area = 0;
  for (std::size_t f = 0; f < c.faces.size(); ++f) uv_area += signed_uv_area(c, f), world_area += w.area[c.faces[f]];
  const double s = uv_area > 0 ? std::sqrt(world_area / uv_area) : 1;
  const double angle = box_angle(c.uv);
  const double cs = std::cos(angle), sn = std::sin(angle);
  V2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (V2& p : c.uv) {
    p = V2{s * (cs * p.x + sn * p.y), s * (-sn * p.x + cs * p.y)};
    lo.x = std::min(lo.x, p.x), lo.y = std::min(lo.y, p.y), hi.x = std::max(hi.x, p.x), hi.y = std::max(hi.y, p.y);
  }
  for (V2& p : c.uv) p.x -= lo.x, p.y -= lo.y;
  c.size = V2{hi.x - lo.x, hi.y - lo.y};
  if (c.size.y > c.size.x) {  // lying flat packs shelves tighter
    for (V2& p : c.uv) p = V2{c.size.y - p.y, p.x};
    c.size = V2{c.size.y, c.size.x};
  }
}

// Shelf packing, tallest first, into rows of at most `shelf_width`;
// returns the side of the square the charts then fit in.
double pack_shelves(std::vector<Chart>& charts, const std::vector<std::size_t>& order, double gutter, double shelf_width) {
  double x = 0, y = 0, shelf_height = 0, used_width = 0;
  for (std::size_t i : order) {
    Chart& c = charts[i];
    if (x > 0 && x + c.size.x + gutter > shelf_width) y += shelf_height, x = 0, shelf_height = 0;
    c.offset = V2{x + 0.5 * gutter, y + 0.5 * gutter};
    x += c.size.x + gutter;
    shelf_height = std::max(shelf_height, c.size.y + gutter);
    used_width = std::max(used_width, x);
  }
  return std::max(used_width, y + shelf_height);
}

// Tries shelf widths from the widest chart to all charts in one row and
// keeps the one that gives the smallest square.
double pack(std::vector<Chart>& charts, double gutter) {
  std::vector<std::size_t> order(charts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return charts[a].size.y > charts[b].size.y; });
  double widest = 0, row = 0;
  for (const Chart& c : charts) widest = std::max(widest, c.size.x + gutter), row += c.size.x + gutter;
  constexpr int kTries = 48;
  double best_width = widest, best_side = 1e300;
  for (int k = 0; k <= kTries; ++k) {
    const double width = widest * std::pow(row / widest, static_cast<double>(k) / kTries);
    const double side = pack_shelves(charts, order, gutter, width);
    if (side < best_side) best_side = side, best_width = width;
  }
  return pack_shelves(charts, order, gutter, best_width);
}

}  // namespace

AtlasMesh parameterize_charts(const TriangleMesh& mesh, int width, int height, const std::string& mesh_name) {
  const WeldedMesh w = weld(mesh);
  std::vector<std::uint32_t> all(w.face.size());
  std::iota(all.begin(), all.end(), 0u);
  std::vector<Chart> charts;
  for (const auto& group : connected_groups(w, all, [&](std::uint32_t f, std::uint32_t g) {
         return normal_class(w.normal[f]) == normal_class(w.normal[g]);
       }))
    flatten(w, group, charts);
  if (charts.empty()) throw std::runtime_error(mesh_name + ": no chart of the mesh could be flattened for its surface texture");
  for (Chart& c : charts) normalise(w, c);

  // The gutter is at least two texels of the final atlas, whose scale
  // depends on the packing, which depends on the gutter: iterate.
  const double texels = std::min(width, height);
  double side = 0;
  for (const Chart& c : charts) side += c.size.x * c.size.y;
  side = std::sqrt(side);
  double gutter = 0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    gutter = 2.5 * side / texels;
    const double packed = pack(charts, gutter);
    if (gutter * texels / packed >= 2.0) {
      side = packed;
      break;
    }
    side = packed;
  }
  if (gutter * texels / side < 2.0)
    throw std::runtime_error(mesh_name + ": surface texture atlas of " + std::to_string(charts.size()) +
                             " charts leaves no two-texel gutter at " + std::to_string(width) + "x" + std::to_string(height) +
                             " texels; raise texture.resolution");

  AtlasMesh atlas;
  for (const Chart& c : charts) {
    const auto base = static_cast<std::uint32_t>(atlas.positions.size());
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      const std::uint32_t source = w.source[c.vertices[i]];
      atlas.positions.push_back(mesh.positions[source]);
      atlas.normals.push_back(mesh.normals.size() == mesh.positions.size() ? mesh.normals[source]
                                                                            : std::array<float, 3>{0, 0, 0});
      atlas.uvs.push_back({static_cast<float>((c.offset.x + c.uv[i].x) / side), static_cast<float>((c.offset.y + c.uv[i].y) / side)});
    }
    for (const auto& l : c.local) atlas.triangles.push_back({base + l[0], base + l[1], base + l[2]});
  }
  return atlas;
}

}  // namespace dp::io
