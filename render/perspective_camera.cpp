#include "perspective_camera.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dp::render {

namespace {
Vec3 to_vec3(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}
}  // namespace

Sample2 sample_concentric_disk(Sample2 u) {
  const float x = 2 * u.u1 - 1, y = 2 * u.u2 - 1;
  if (x == 0 && y == 0) return {0, 0};
  constexpr float quarter_pi = std::numbers::pi_v<float> / 4;
  float r, theta;
  if (std::abs(x) > std::abs(y)) {
    r = x;
    theta = quarter_pi * (y / x);
  } else {
    r = y;
    theta = 2 * quarter_pi - quarter_pi * (x / y);
  }
  return {r * std::cos(theta), r * std::sin(theta)};
}

PerspectiveCamera::PerspectiveCamera(const dp::io::CameraSettings& s, int width, int height)
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
  if (s.model == dp::io::CameraModel::ThinLens) {
    aperture_radius_ = static_cast<float>(s.aperture_radius_m);
    focus_distance_ = s.focus_distance_m > 0 ? static_cast<float>(s.focus_distance_m) : length(view);
  }
}

Ray PerspectiveCamera::ray_through(float x, float y, Sample2 lens) const {
  const float along_right = (x - half_width_) * pixel_size_;
  const float along_up = (half_height_ - y) * pixel_size_;
  const Vec3 direction = forward_ + along_right * right_ + along_up * up_;
  if (aperture_radius_ <= 0) return {position_, normalize(direction)};
  // Every ray through this film point meets the pinhole ray on the plane in
  // focus, which lies focus_distance_ ahead along the optical axis.
  const Vec3 in_focus = position_ + focus_distance_ * direction;
  const Sample2 d = sample_concentric_disk(lens);
  const Vec3 origin = position_ + aperture_radius_ * (d.u1 * right_ + d.u2 * up_);
  return {origin, normalize(in_focus - origin)};
}

}  // namespace dp::render
