#pragma once
// A scene material (render.materials.NAME) as the renderer uses it: the BSDF
// it has at a surface point, given that point's condensed water, and the
// light it emits or absorbs.
//
// The roughness follows the paper's rendering of steamed surfaces
// (Hochstetter & Kolb 2017, Sec. 8: "a rough material where the roughness
// was controlled by the water mass textures"):
//   alpha = lerp(alpha_dry, alpha_fogged, clamp(m_t / m_t^max, 0, 1)),
// and, where wet paths are on, a texel a drop has run over (wetting history
// w) moves towards the wet roughness and darkens:
//   alpha <- lerp(alpha, alpha_wet, w),   reflectance *= 1 - darkening * w.
#include "bsdf.h"
#include "render_settings.h"
#include "rgb.h"

namespace dp::render {

// What the simulator's surface texture says about a point (all in [0, 1]).
struct SurfaceState {
  float fog = 0;      // m_t / m_t^max, clamped
  float wetting = 0;  // wetting history
};

class Material {
 public:
  Material(const dp::io::Material& description, bool wet_paths);

  Bsdf bsdf_at(SurfaceState state) const;
  float roughness_at(SurfaceState state) const;
  // Radiance leaving the front (outside) of an emissive surface.
  Rgb emission() const { return emission_; }
  bool emissive() const { return !is_black(emission_); }
  // Beer-Lambert absorption coefficient of the object's inside (1/m); zero
  // for opaque objects and clear media.
  Rgb absorption_per_m() const { return absorption_per_m_; }

 private:
  dp::io::MaterialType type_;
  Rgb albedo_, eta_, k_;
  float ior_;
  float alpha_dry_, alpha_fogged_, alpha_wet_, wet_darkening_;
  bool wet_paths_;
  Rgb emission_, absorption_per_m_;
};

}  // namespace dp::render
