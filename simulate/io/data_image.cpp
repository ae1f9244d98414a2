#include "data_image.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfTestFile.h>
#include <stb_image.h>
#include <stb_image_resize.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace dp::io {
namespace {

constexpr double kLumaR = 0.2126, kLumaG = 0.7152, kLumaB = 0.0722;

DataImage read_exr(const std::filesystem::path& file) {
  Imf::InputFile in(file.c_str());
  const Imath::Box2i window = in.header().dataWindow();
  DataImage image;
  image.width = window.max.x - window.min.x + 1;
  image.height = window.max.y - window.min.y + 1;
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  const Imf::ChannelList& channels = in.header().channels();
  std::vector<std::string> names;
  for (auto c = channels.begin(); c != channels.end(); ++c) names.emplace_back(c.name());
  const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
  std::vector<std::string> wanted;
  if (rgb) wanted = {"R", "G", "B"};
  else if (channels.findChannel("Y")) wanted = {"Y"};
  else if (names.size() == 1) wanted = names;
  else throw std::runtime_error(file.string() + ": expected channels R, G, B, or Y, or a single channel; found " +
                                std::to_string(names.size()) + " others");
  std::vector<std::vector<float>> planes(wanted.size(), std::vector<float>(n));
  Imf::FrameBuffer buffer;
  for (std::size_t c = 0; c < wanted.size(); ++c) {
    // The slice's base is where pixel (0, 0) would lie, which may be outside
    // the data window.
    char* base = reinterpret_cast<char*>(planes[c].data()) -
                 (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * image.width) *
                     static_cast<std::ptrdiff_t>(sizeof(float));
    buffer.insert(wanted[c], Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * image.width));
  }
  in.setFrameBuffer(buffer);
  in.readPixels(window.min.y, window.max.y);
  image.values.resize(n);
  for (std::size_t p = 0; p < n; ++p)
    image.values[p] = rgb ? static_cast<float>(kLumaR * planes[0][p] + kLumaG * planes[1][p] + kLumaB * planes[2][p])
                          : planes[0][p];
  return image;
}

DataImage read_with_stb(const std::filesystem::path& file) {
  int width = 0, height = 0, channels = 0;
  // 16-bit samples whatever the file holds: stb_image widens 8-bit ones to
  // v * 257, so v / 65535 is v / 255 exactly.
  std::unique_ptr<stbi_us, void (*)(void*)> pixels(stbi_load_16(file.c_str(), &width, &height, &channels, 0), stbi_image_free);
  if (!pixels) throw std::runtime_error(file.string() + ": cannot read the image: " + stbi_failure_reason());
  DataImage image;
  image.width = width;
  image.height = height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  image.values.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const stbi_us* v = pixels.get() + p * channels;
    // Grey or grey + alpha: the grey; RGB or RGBA: the luminance. Alpha is
    // not a mass and is ignored.
    const double value = channels >= 3 ? kLumaR * v[0] + kLumaG * v[1] + kLumaB * v[2] : v[0];
    image.values[p] = static_cast<float>(value / 65535.0);
  }
  return image;
}

stbir_filter filter_for(int from, int to) { return to >= from ? STBIR_FILTER_CATMULLROM : STBIR_FILTER_MITCHELL; }

}  // namespace

DataImage read_data_image(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) throw std::runtime_error(file.string() + ": cannot read the image: no such file");
  try {
    if (Imf::isOpenExrFile(file.c_str())) return read_exr(file);
  } catch (const std::exception& e) {
    const std::string what = e.what();
    if (what.rfind(file.string(), 0) == 0) throw;
    throw std::runtime_error(file.string() + ": cannot read the OpenEXR image: " + what);
  }
  return read_with_stb(file);
}

DataImage resample(const DataImage& image, int width, int height) {
  if (image.width == width && image.height == height) return image;
  DataImage out;
  out.width = width;
  out.height = height;
  out.values.resize(static_cast<std::size_t>(width) * height);
  const int ok = stbir_resize(image.values.data(), image.width, image.height, 0, out.values.data(), width, height, 0,
                              STBIR_TYPE_FLOAT, 1, STBIR_ALPHA_CHANNEL_NONE, 0, STBIR_EDGE_CLAMP, STBIR_EDGE_CLAMP,
                              filter_for(image.width, width), filter_for(image.height, height), STBIR_COLORSPACE_LINEAR,
                              nullptr);
  if (!ok) throw std::runtime_error("cannot resample an image of " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " to " + std::to_string(width) + "x" + std::to_string(height));
  return out;
}

}  // namespace dp::io
