#pragma once
// A rendered frame: linear RGB radiance per pixel, rows top to bottom.
#include <vector>

#include "rgb.h"

namespace dp::render {

struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;

  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}
  Rgb& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
  const Rgb& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

}  // namespace dp::render
