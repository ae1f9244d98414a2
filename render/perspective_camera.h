#pragma once
// A perspective camera: an ideal pinhole, or a thin lens (pbrt-v4 Sec.
// 5.2.3) whose aperture disk blurs everything off the plane in focus. A
// thin lens with aperture radius 0 is the pinhole.
#include "ray.h"
#include "render_settings.h"
#include "sampling.h"

namespace dp::render {

class PerspectiveCamera {
 public:
  // The vertical field of view fixes the image height; the width follows
  // from the aspect ratio of width x height pixels. Throws
  // std::invalid_argument for a degenerate view.
  PerspectiveCamera(const dp::io::CameraSettings& settings, int width, int height);

  // The ray through film position (x, y) in pixels, (0, 0) being the top
  // left corner of the image and (width, height) the bottom right; `lens`
  // places its origin on the aperture (ignored by a pinhole).
  Ray ray_through(float x, float y, Sample2 lens = {0.5f, 0.5f}) const;

  Vec3 position() const { return position_; }
  Vec3 forward() const { return forward_; }
  float focus_distance() const { return focus_distance_; }
  float aperture_radius() const { return aperture_radius_; }

 private:
  Vec3 position_;
  Vec3 forward_, right_, up_;  // right_ and up_ span the image plane at unit distance
  float pixel_size_;           // on that plane
  float half_width_, half_height_;  // in pixels
  float aperture_radius_ = 0, focus_distance_ = 1;
};

// A point on the unit disk, uniform in area, by Shirley & Chiu's 1997
// concentric map (keeps strata compact).
Sample2 sample_concentric_disk(Sample2 u);

}  // namespace dp::render
