#include "surface_frames.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <stdexcept>

#include "atomic_file.h"
#include "ply.h"

namespace dp::io {

void write_rigid_atlas_mesh(const std::filesystem::path& file, const AtlasMesh& atlas, const std::string& comment) {
  PlyData ply;
  ply.comments.push_back(comment);
  ply.comments.push_back("uv " + atlas.uv_source);
  const std::size_t n = atlas.positions.size();
  ply.vertex_count = n;
  auto column = [&](auto value) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = value(i);
    return v;
  };
  const char* axes[3] = {"x", "y", "z"};
  const char* normal_axes[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a) ply.add(axes[a], PlyType::Float32, column([&](std::size_t i) { return atlas.positions[i][a]; }));
  for (int a = 0; a < 3; ++a) ply.add(normal_axes[a], PlyType::Float32, column([&](std::size_t i) { return atlas.normals[i][a]; }));
  ply.add("s", PlyType::Float32, column([&](std::size_t i) { return atlas.uvs[i][0]; }));
  ply.add("t", PlyType::Float32, column([&](std::size_t i) { return atlas.uvs[i][1]; }));
  ply.faces = atlas.triangles;
  write_ply(file, ply);
}

void write_surface_frame(const std::filesystem::path& file, const SurfaceSnapshot& s) {
  const int channels = static_cast<int>(surface_channel_names().size());
  std::vector<float> pixels(static_cast<std::size_t>(s.width) * s.height * channels, 0.0f);
  for (std::size_t t = 0; t < s.size(); ++t) {
    float* p = &pixels[static_cast<std::size_t>(s.pixel[t]) * channels];
    p[0] = static_cast<float>(kg_of_texel_units(s.mass_units[t], s.kg_per_unit));
    p[1] = s.max_mass[t];
    p[2] = s.temperature[t];
    p[3] = s.wetting[t];
  }
  // OpenEXR writes no time stamp or host name of its own, so a frame's bytes
  // depend on the simulation alone (a resumed run and image diffs compare
  // them). Channels are stored in name order, which is already theirs.
  Imf::Header header(s.width, s.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  Imf::FrameBuffer buffer;
  const auto& names = surface_channel_names();
  const std::size_t pixel_stride = sizeof(float) * channels;
  for (int c = 0; c < channels; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    buffer.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), pixel_stride,
                                       pixel_stride * static_cast<std::size_t>(s.width)));
  }
  const std::filesystem::path temporary = temporary_path_for(file);
  try {
    Imf::OutputFile out(temporary.c_str(), header);
    out.setFrameBuffer(buffer);
    out.writePixels(s.height);
  } catch (const std::exception& e) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(file.string() + ": cannot write surface textures: " + e.what());
  }
  commit_temporary(temporary, file);
}

}  // namespace dp::io
