#include "surface_frames.h"

#include <OpenImageIO/imageio.h>

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
  OIIO::ImageSpec spec(s.width, s.height, channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = surface_channel_names();
  spec.attribute("compression", "zip");
  // OpenImageIO stamps the time of writing unless told one; a frame's bytes
  // must depend on the simulation alone (a resumed run and image diffs
  // compare them), so the stamp is a fixed, documented value.
  spec.attribute("DateTime", "1970:01:01 00:00:00");
  // OpenImageIO picks the format from the name, and the temporary name's
  // extension is not .exr: the format is named.
  const std::filesystem::path temporary = temporary_path_for(file);
  auto out = OIIO::ImageOutput::create("openexr");
  if (!out) throw std::runtime_error(file.string() + ": OpenImageIO cannot write OpenEXR: " + OIIO::geterror());
  const bool written = out->open(temporary.string(), spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && out->close();
  if (!written) {
    const std::string error = out->geterror();
    out.reset();
    std::filesystem::remove(temporary);
    throw std::runtime_error(file.string() + ": cannot write surface textures: " + error);
  }
  out.reset();
  commit_temporary(temporary, file);
}

}  // namespace dp::io
