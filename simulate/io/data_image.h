#pragma once
// An image read as data: one float per pixel, the luminance of RGB (Rec. 709
// weights) or the single grey channel, no colour transform, row 0 at the top.
#include <filesystem>
#include <vector>

namespace dp::io {

struct DataImage {
  int width = 0, height = 0;
  std::vector<float> values;  // width * height, row-major from the top row
};

// OpenEXR (by its magic number, whatever the extension) through OpenEXR: the
// luminance of R, G, B, else Y, else the only channel. Any other format
// through stb_image, 8-bit values v as v / 255 and 16-bit ones as v / 65535.
// Throws std::runtime_error naming the file when it cannot be read.
DataImage read_data_image(const std::filesystem::path& file);

// Resampled to width x height: Catmull-Rom along an axis that grows or keeps
// its size (it interpolates, so an image already at the size is returned as
// it is), Mitchell-Netravali along one that shrinks (it filters, so a large
// image does not alias); edges clamp.
DataImage resample(const DataImage& image, int width, int height);

}  // namespace dp::io
