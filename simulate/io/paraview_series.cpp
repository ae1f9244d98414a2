#include "paraview_series.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <sstream>

#include "atomic_file.h"
#include "frames.h"

namespace dp::io {

namespace {

// VTK XML's "appended raw" layout: the XML names each array with its offset
// into one binary block after the XML, where every array is its byte count
// (UInt64, header_type) followed by its bytes. Written little-endian, as the
// files say; every target we build for is.
class AppendedArrays {
 public:
  // Appends the values and returns the array's XML tag, a line of its own.
  template <class T>
  std::string add(const std::string& name, const char* vtk_type, int components, const std::vector<T>& values) {
    std::ostringstream xml;
    xml << "    <DataArray type=\"" << vtk_type << "\"";
    if (!name.empty()) xml << " Name=\"" << name << "\"";
    xml << " NumberOfComponents=\"" << components << "\" format=\"appended\" offset=\"" << data_.size() << "\"/>\n";
    const std::uint64_t bytes = values.size() * sizeof(T);
    append(&bytes, sizeof bytes);
    append(values.data(), bytes);
    return xml.str();
  }
  void write_data(std::ostream& out) const {
    out << "  <AppendedData encoding=\"raw\">\n_";
    out.write(data_.data(), static_cast<std::streamsize>(data_.size()));
    out << "\n  </AppendedData>\n";
  }

 private:
  void append(const void* p, std::size_t n) {
    const std::size_t at = data_.size();
    data_.resize(at + n);
    if (n > 0) std::memcpy(data_.data() + at, p, n);
  }
  std::vector<char> data_;
};

template <class T, class F>
std::vector<T> column(std::size_t n, const F& f) {
  std::vector<T> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = f(i);
  return v;
}

std::vector<float> flatten(const std::vector<Vec3>& v) {
  std::vector<float> out;
  out.reserve(3 * v.size());
  for (const Vec3& p : v) out.insert(out.end(), {p.x, p.y, p.z});
  return out;
}

void write_header(std::ostream& out, const char* type) {
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"" << type
      << "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
}

}  // namespace

void write_particles_vtp(const std::filesystem::path& file, const ParticleSnapshot& p, float radius) {
  const std::size_t n = p.size();
  AppendedArrays a;
  // Point data, in the order of the PLY's vertex properties (file-formats.md).
  // One statement per array: the block's layout follows the order of the calls.
  std::string point_data;
  point_data += a.add("velocity", "Float32", 3, flatten(p.velocity));
  point_data += a.add("weight", "Float32", 1, p.weight);
  point_data += a.add("radius", "Float32", 1, column<float>(n, [&](std::size_t i) { return particle_radius_of(radius, p.weight[i]); }));
  point_data += a.add("temperature", "Float32", 1, p.temperature);
  point_data += a.add("density", "Float32", 1, p.density);
  point_data += a.add("pressure", "Float32", 1, p.pressure);
  point_data += a.add("surface_area", "Float32", 1, p.surface_area);
  point_data += a.add("id", "UInt32", 1, p.id);
  const std::string points = a.add("", "Float32", 3, flatten(p.position));
  // One vertex cell per particle, so that every representation shows them.
  std::string verts;
  verts += a.add("connectivity", "Int64", 1, column<std::int64_t>(n, [](std::size_t i) { return static_cast<std::int64_t>(i); }));
  verts += a.add("offsets", "Int64", 1, column<std::int64_t>(n, [](std::size_t i) { return static_cast<std::int64_t>(i + 1); }));
  write_atomically(file, [&](std::ostream& out) {
    write_header(out, "PolyData");
    out << " <PolyData>\n  <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "   <PointData Scalars=\"temperature\" Vectors=\"velocity\">\n" << point_data << "   </PointData>\n"
        << "   <Points>\n" << points << "   </Points>\n   <Verts>\n" << verts << "   </Verts>\n  </Piece>\n </PolyData>\n";
    a.write_data(out);
    out << "</VTKFile>\n";
  });
}

void write_air_vti(const std::filesystem::path& file, const AirSnapshot& air) {
  const MacGrid& g = air.grid;
  const std::size_t cells = g.cell_count();
  std::vector<Vec3> velocity(cells);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) velocity[g.cell(i, j, k)] = air.cell_velocity(i, j, k);
  AppendedArrays a;
  std::string cell_data;
  cell_data += a.add("vapor_density", "Float32", 1, column<float>(cells, [&](std::size_t c) { return static_cast<float>(air.vapor[c]); }));
  cell_data += a.add("temperature", "Float32", 1, air.temperature);
  cell_data += a.add("velocity", "Float32", 3, flatten(velocity));
  cell_data += a.add("kind", "UInt8", 1, air.kind);
  write_atomically(file, [&](std::ostream& out) {
    write_header(out, "ImageData");
    // Cells in x-fastest order, as VTK's image cells are.
    out << " <ImageData WholeExtent=\"0 " << g.nx << " 0 " << g.ny << " 0 " << g.nz << "\" Origin=\"" << g.origin.x << " "
        << g.origin.y << " " << g.origin.z << "\" Spacing=\"" << g.dx << " " << g.dx << " " << g.dx << "\">\n"
        << "  <Piece Extent=\"0 " << g.nx << " 0 " << g.ny << " 0 " << g.nz << "\">\n"
        << "   <CellData Scalars=\"vapor_density\" Vectors=\"velocity\">\n" << cell_data << "   </CellData>\n"
        << "  </Piece>\n </ImageData>\n";
    a.write_data(out);
    out << "</VTKFile>\n";
  });
}

void write_pvd(const std::filesystem::path& file, const std::vector<SeriesFrame>& frames) {
  write_atomically(file, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n <Collection>\n";
    out.precision(17);
    for (const SeriesFrame& f : frames) {
      out << "  <DataSet timestep=\"" << f.time_s << "\" part=\"0\" name=\"particles\" file=\"" << f.particles_file << "\"/>\n";
      if (!f.air_file.empty())
        out << "  <DataSet timestep=\"" << f.time_s << "\" part=\"1\" name=\"air\" file=\"" << f.air_file << "\"/>\n";
    }
    out << " </Collection>\n</VTKFile>\n";
  });
}

}  // namespace dp::io
