#pragma once
// Meshes for the surface-atlas tests, written as OBJ files here and loaded
// back through assimp like any asset.
#include <unistd.h>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace dp::io::test {

inline std::filesystem::path test_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("dewpoint-surface-io-test-" + std::to_string(::getpid())) / name;
  std::filesystem::create_directories(dir);
  return dir;
}

// A w x d rectangle in the plane y = 0, n x n quads, UVs spanning
// [u0, u1]^2; `mirrored` maps its right half onto the same UVs as its left.
inline std::filesystem::path plane_with_uvs(const std::string& name, float w, float d, int n, float u0, float u1,
                                            bool mirrored = false) {
  auto file = test_dir("meshes") / (name + ".obj");
  std::ofstream out(file);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      float s = static_cast<float>(i) / n, t = static_cast<float>(j) / n;
      out << "v " << w * s << " 0 " << -d * t << "\n";
      float us = mirrored ? (s <= 0.5f ? 2 * s : 2 - 2 * s) : s;
      out << "vt " << u0 + (u1 - u0) * us << " " << u0 + (u1 - u0) * t << "\n";
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, e = a + n + 1;
      out << "f " << a << "/" << a << " " << b << "/" << b << " " << c << "/" << c << "\n";
      out << "f " << a << "/" << a << " " << c << "/" << c << " " << e << "/" << e << "\n";
    }
  return file;
}

// The unit cube [-0.5, 0.5]^3, outward faces, no UVs.
inline std::filesystem::path cube_without_uvs() {
  auto file = test_dir("meshes") / "cube.obj";
  std::ofstream out(file);
  for (int k = 0; k < 8; ++k) out << "v " << ((k & 1) ? 0.5 : -0.5) << " " << ((k & 2) ? 0.5 : -0.5) << " " << ((k & 4) ? 0.5 : -0.5) << "\n";
  const int quads[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
  for (const auto& q : quads) out << "f " << q[0] << " " << q[1] << " " << q[2] << "\n" << "f " << q[0] << " " << q[2] << " " << q[3] << "\n";
  return file;
}

// The unit icosphere subdivided `levels` times, outward faces, no UVs.
inline std::filesystem::path sphere_without_uvs(int levels) {
  std::vector<std::array<double, 3>> v;
  auto add = [&](double x, double y, double z) {
    double l = std::sqrt(x * x + y * y + z * z);
    v.push_back({x / l, y / l, z / l});
    return static_cast<int>(v.size() - 1);
  };
  const double p = (1 + std::sqrt(5.0)) / 2;
  for (auto [x, y, z] : std::vector<std::array<double, 3>>{{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                                                           {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}})
    add(x, y, z);
  std::vector<std::array<int, 3>> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto middle = [&](int a, int b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      int m = add(v[a][0] + v[b][0], v[a][1] + v[b][1], v[a][2] + v[b][2]);
      mid[key] = m;
      return m;
    };
    std::vector<std::array<int, 3>> next;
    for (auto [a, b, c] : f) {
      int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    f = next;
  }
  auto file = test_dir("meshes") / ("sphere" + std::to_string(levels) + ".obj");
  std::ofstream out(file);
  out.precision(9);
  for (auto& x : v) out << "v " << x[0] << " " << x[1] << " " << x[2] << "\n";
  for (auto& t : f) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return file;
}

// A torus (radii R, r) of n x m quads, outward faces, no UVs: genus one, so
// some of its normal-direction charts are rings, not discs.
inline std::filesystem::path torus_without_uvs(double R, double r, int n, int m) {
  auto file = test_dir("meshes") / "torus.obj";
  std::ofstream out(file);
  out.precision(9);
  const double pi = 3.14159265358979;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / m;
      out << "v " << (R + r * std::cos(v)) * std::cos(u) << " " << r * std::sin(v) << " " << (R + r * std::cos(v)) * std::sin(u) << "\n";
    }
  auto id = [&](int i, int j) { return ((i % n) * m + (j % m)) + 1; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      out << "f " << id(i, j) << " " << id(i, j + 1) << " " << id(i + 1, j + 1) << "\n";
      out << "f " << id(i, j) << " " << id(i + 1, j + 1) << " " << id(i + 1, j) << "\n";
    }
  return file;
}

}  // namespace dp::io::test
