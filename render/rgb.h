#pragma once
// Linear RGB radiance, reflectance or path throughput. Three fixed channels
// stand in for a spectrum, as the scene file's colours are RGB.
#include <algorithm>
#include <array>

namespace dp::render {

struct Rgb {
  float r = 0, g = 0, b = 0;

  static Rgb gray(float v) { return {v, v, v}; }
  static Rgb from(const std::array<double, 3>& c) {
    return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
  }

  float operator[](int channel) const { return channel == 0 ? r : (channel == 1 ? g : b); }
  Rgb& operator+=(Rgb o) { r += o.r; g += o.g; b += o.b; return *this; }
  Rgb& operator*=(Rgb o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
  Rgb& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
};

inline Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
inline Rgb operator*(Rgb a, Rgb b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
inline Rgb operator*(float s, Rgb c) { return {s * c.r, s * c.g, s * c.b}; }
inline Rgb operator*(Rgb c, float s) { return s * c; }

inline float max_component(Rgb c) { return std::max({c.r, c.g, c.b}); }
inline bool is_black(Rgb c) { return c.r == 0 && c.g == 0 && c.b == 0; }

// Mixes a and b: t = 0 gives a, t = 1 gives b.
inline Rgb lerp(Rgb a, Rgb b, float t) { return (1 - t) * a + t * b; }

}  // namespace dp::render
