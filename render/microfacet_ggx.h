#pragma once
// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, in the
// local shading frame (z = macro-surface normal):
//   D     Walter, Marschner, Li & Torrance 2007, "Microfacet Models for
//         Refraction through Rough Surfaces", Eq. 33;
//   Λ, G  Smith masking with GGX's Λ, in the height-correlated form
//         G = 1 / (1 + Λ(wo) + Λ(wi)) of Heitz 2014, "Understanding the
//         Masking-Shadowing Function in Microfacet-Based BRDFs", Eq. 99
//         (Walter's separable G1·G1 is its uncorrelated approximation;
//         see docs/paper-map.md, departures);
//   sampling of the normals visible from wo, Heitz 2018, "Sampling the
//         GGX Distribution of Visible Normals", Listing 1.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sampling.h"
#include "vec3.h"

namespace dp::render {

class GgxDistribution {
 public:
  explicit GgxDistribution(float alpha) : alpha_(alpha) {}

  float alpha() const { return alpha_; }
  // Below this the distribution is a Dirac delta for every purpose a float
  // can tell apart; materials then scatter specularly.
  bool effectively_smooth() const { return alpha_ < 1e-3f; }

  // Density of micro-normals per unit projected area (Walter Eq. 33).
  float D(Vec3 m) const {
    if (m.z <= 0) return 0;
    const float a2 = alpha_ * alpha_;
    const float cos2 = m.z * m.z;
    const float denominator = 1 + (a2 - 1) * cos2;
    return a2 / (std::numbers::pi_v<float> * denominator * denominator);
  }

  // Smith's Λ for GGX: Λ(w) = (-1 + sqrt(1 + α² tan²θ)) / 2.
  float lambda(Vec3 w) const {
    const float cos2 = w.z * w.z;
    if (cos2 == 0) return INFINITY;
    const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
    return 0.5f * (-1 + std::sqrt(1 + alpha_ * alpha_ * tan2));
  }
  float G1(Vec3 w) const { return 1 / (1 + lambda(w)); }
  float G(Vec3 wo, Vec3 wi) const { return 1 / (1 + lambda(wo) + lambda(wi)); }

  // Density of the normals visible from w: G1(w) max(0, w·m) D(m) / |w.z|
  // (Heitz 2018 Eq. 1), over solid angle of m.
  float visible_normal_pdf(Vec3 w, Vec3 m) const {
    if (w.z == 0) return 0;
    return G1(w) * std::max(0.0f, dot(w, m)) * D(m) / std::abs(w.z);
  }

  // A micro-normal drawn with visible_normal_pdf(w', m), w' = w mirrored into
  // the upper hemisphere (Heitz 2018, Listing 1).
  Vec3 sample_visible_normal(Vec3 w, Sample2 u) const {
    const Vec3 upper = w.z < 0 ? -w : w;
    const Vec3 vh = normalize(Vec3{alpha_ * upper.x, alpha_ * upper.y, upper.z});
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lensq > 0 ? (1 / std::sqrt(lensq)) * Vec3{-vh.y, vh.x, 0} : Vec3{1, 0, 0};
    const Vec3 t2 = cross(vh, t1);
    const float r = std::sqrt(u.u1);
    const float phi = 2 * std::numbers::pi_v<float> * u.u2;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1 + vh.z);
    const float p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2)) * vh;
    return normalize(Vec3{alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)});
  }

 private:
  float alpha_;
};

}  // namespace dp::render
