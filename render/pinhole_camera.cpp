#include "pinhole_camera.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dp::render {

namespace {
Vec3 to_vec3(const dp::io::Vec3d& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}
}  // namespace

PinholeCamera::PinholeCamera(const dp::io::CameraSettings& s, int width, int height)
    : position_(to_vec3(s.position_m)), half_width_(0.5f * static_cast<float>(width)), half_height_(0.5f * static_cast<float>(height)) {
  const Vec3 view = to_vec3(s.look_at_m) - position_;
  const Vec3 right = cross(view, to_vec3(s.up));
  if (!(length(view) > 0) || !(length(right) > 0))
    throw std::invalid_argument("render.camera: look_at_m must differ from position_m and not lie along up");
  forward_ = normalize(view);
  right_ = normalize(right);
  up_ = cross(right_, forward_);
  const double half_fov = 0.5 * s.fov_deg * std::numbers::pi / 180;
  pixel_size_ = static_cast<float>(std::tan(half_fov) / half_height_);
}

Ray PinholeCamera::ray_through(float x, float y) const {
  const float along_right = (x - half_width_) * pixel_size_;
  const float along_up = (half_height_ - y) * pixel_size_;
  return {position_, normalize(forward_ + along_right * right_ + along_up * up_)};
}

}  // namespace dp::render
