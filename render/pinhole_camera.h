#pragma once
// An ideal pinhole camera: no depth of field, no distortion.
#include "ray.h"
#include "scene.h"

namespace dp::render {

class PinholeCamera {
 public:
  // The vertical field of view fixes the image height; the width follows
  // from the aspect ratio of width x height pixels.
  PinholeCamera(const dp::io::CameraSettings& settings, int width, int height);

  // The ray through film position (x, y) in pixels, (0, 0) being the top
  // left corner of the image and (width, height) the bottom right.
  Ray ray_through(float x, float y) const;

 private:
  Vec3 position_;
  Vec3 forward_, right_, up_;  // right_ and up_ span the image plane at unit distance
  float pixel_size_;           // on that plane
  float half_width_, half_height_;  // in pixels
};

}  // namespace dp::render
