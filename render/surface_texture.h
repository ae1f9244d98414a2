#pragma once
// One rigid's surface texture of one frame, as dewpoint-simulate writes it
// (docs/file-formats.md, surface_NAME.%04d.exr): float channels `mass`,
// `max_mass`, `temperature` and `wetting` over the rigid's UV atlas, row 0
// at the top (v = 1 - (row + 0.5) / height, u = (col + 0.5) / width).
// The renderer needs the fogged fraction m_t / m_t^max and the wetting
// history, read bilinearly between texel centres.
#include <filesystem>
#include <vector>

#include "material.h"

namespace dp::render {

class SurfaceTexture {
 public:
  // Throws std::runtime_error naming the file and the missing channel.
  static SurfaceTexture load(const std::filesystem::path& file);
  // mass, max_mass, wetting: width * height each, rows from the top.
  SurfaceTexture(int width, int height, const std::vector<float>& mass, const std::vector<float>& max_mass,
                 const std::vector<float>& wetting);

  int width() const { return width_; }
  int height() const { return height_; }

  // Bilinear between the four nearest texel centres, clamped at the atlas
  // edge. Texels outside every chart (m_t^max = 0) hold no surface; their
  // weight goes to the chart's own texels, so a chart's border does not
  // fade towards dry.
  SurfaceState at(float u, float v) const;

 private:
  struct Texel {
    float fog = 0, wetting = 0;
    bool in_chart = false;
  };
  const Texel& texel(int col, int row) const;

  int width_ = 0, height_ = 0;
  std::vector<Texel> texels_;
};

}  // namespace dp::render
