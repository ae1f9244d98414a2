#include "ply.h"

#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "atomic_file.h"

namespace dp::io {

namespace {

const char* type_name(PlyType t) {
  switch (t) {
    case PlyType::Float32: return "float";
    case PlyType::Float64: return "double";
    case PlyType::UInt8: return "uchar";
    case PlyType::Int32: return "int";
    case PlyType::UInt32: return "uint";
  }
  return "?";
}

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::Float64: return 8;
    case PlyType::UInt8: return 1;
    default: return 4;
  }
}

bool parse_type(const std::string& s, PlyType& t) {
  if (s == "float" || s == "float32") t = PlyType::Float32;
  else if (s == "double" || s == "float64") t = PlyType::Float64;
  else if (s == "uchar" || s == "uint8") t = PlyType::UInt8;
  else if (s == "int" || s == "int32") t = PlyType::Int32;
  else if (s == "uint" || s == "uint32") t = PlyType::UInt32;
  else return false;
  return true;
}

template <class T>
void put(std::ostream& out, T v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));  // little-endian hosts only (x86-64, arm64)
}

void put_value(std::ostream& out, PlyType t, double v) {
  switch (t) {
    case PlyType::Float32: put(out, static_cast<float>(v)); break;
    case PlyType::Float64: put(out, v); break;
    case PlyType::UInt8: put(out, static_cast<std::uint8_t>(v)); break;
    case PlyType::Int32: put(out, static_cast<std::int32_t>(v)); break;
    case PlyType::UInt32: put(out, static_cast<std::uint32_t>(v)); break;
  }
}

double get_value(const char* p, PlyType t) {
  switch (t) {
    case PlyType::Float32: { float v; std::memcpy(&v, p, 4); return v; }
    case PlyType::Float64: { double v; std::memcpy(&v, p, 8); return v; }
    case PlyType::UInt8: return static_cast<unsigned char>(*p);
    case PlyType::Int32: { std::int32_t v; std::memcpy(&v, p, 4); return v; }
    case PlyType::UInt32: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
  }
  return 0;
}

struct FaceLayout {
  bool present = false;
  PlyType count_type = PlyType::UInt8, index_type = PlyType::Int32;
};

}  // namespace

void PlyData::add(const std::string& name, PlyType type, std::vector<double> values) {
  if (values.size() != vertex_count)
    throw std::logic_error("PLY property '" + name + "' has " + std::to_string(values.size()) + " values for " +
                           std::to_string(vertex_count) + " vertices");
  vertex.push_back(PlyProperty{name, type, std::move(values)});
}

const PlyProperty* PlyData::find(const std::string& name) const {
  for (const auto& p : vertex)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<float> PlyData::floats(const std::string& name) const {
  const PlyProperty* p = find(name);
  if (!p) throw std::runtime_error("PLY has no vertex property '" + name + "'");
  return std::vector<float>(p->values.begin(), p->values.end());
}

void write_ply(const std::filesystem::path& path, const PlyData& data) {
  write_atomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\n";
    for (const auto& c : data.comments) out << "comment " << c << "\n";
    out << "element vertex " << data.vertex_count << "\n";
    for (const auto& p : data.vertex) out << "property " << type_name(p.type) << " " << p.name << "\n";
    if (!data.faces.empty()) out << "element face " << data.faces.size() << "\nproperty list uchar int vertex_indices\n";
    out << "end_header\n";
    for (std::size_t i = 0; i < data.vertex_count; ++i)
      for (const auto& p : data.vertex) put_value(out, p.type, p.values[i]);
    for (const auto& f : data.faces) {
      put<std::uint8_t>(out, 3);
      for (std::uint32_t v : f) put<std::int32_t>(out, static_cast<std::int32_t>(v));
    }
  });
}

PlyData read_ply(const std::filesystem::path& path) {
  auto fail = [&](const std::string& what) { return std::runtime_error(path.string() + ": " + what); };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open PLY file");

  std::string line;
  std::getline(in, line);
  if (line != "ply") throw fail("not a PLY file (first line is '" + line + "', expected 'ply')");

  PlyData data;
  bool binary = true;
  FaceLayout face;
  std::size_t face_count = 0;
  std::string element;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "end_header") break;
    if (word == "comment" || word == "obj_info") {
      if (line.size() > 8) data.comments.push_back(line.substr(8));
    } else if (word == "format") {
      std::string fmt;
      s >> fmt;
      if (fmt == "ascii") binary = false;
      else if (fmt != "binary_little_endian") throw fail("line " + std::to_string(line_no) + ": unsupported PLY format '" + fmt + "' (expected binary_little_endian or ascii)");
    } else if (word == "element") {
      long long signed_count = -1;
      s >> element >> signed_count;
      if (!s || signed_count < 0)
        throw fail("line " + std::to_string(line_no) + ": element '" + element + "' needs a non-negative count");
      const auto count = static_cast<std::size_t>(signed_count);
      if (element == "vertex") data.vertex_count = count;
      else if (element == "face") face_count = count;
      else throw fail("line " + std::to_string(line_no) + ": unsupported element '" + element + "'");
    } else if (word == "property") {
      std::string type;
      s >> type;
      if (type == "list") {
        std::string ct, it, name;
        s >> ct >> it >> name;
        if (element != "face" || !parse_type(ct, face.count_type) || !parse_type(it, face.index_type))
          throw fail("line " + std::to_string(line_no) + ": unsupported list property");
        face.present = true;
      } else {
        PlyType t;
        std::string name;
        s >> name;
        if (!parse_type(type, t)) throw fail("line " + std::to_string(line_no) + ": unknown property type '" + type + "'");
        if (element != "vertex") throw fail("line " + std::to_string(line_no) + ": scalar properties are supported on vertices only");
        data.vertex.push_back(PlyProperty{name, t, {}});
      }
    } else if (!word.empty()) {
      throw fail("line " + std::to_string(line_no) + ": unexpected header line '" + line + "'");
    }
  }
  if (!in) throw fail("header has no end_header line");
  if (face_count > 0 && !face.present) throw fail("face element without vertex_indices list");
  // Vertices without properties occupy no bytes, so the size check below
  // cannot bound their count; nothing we read has such vertices.
  if (data.vertex_count > 0 && data.vertex.empty())
    throw fail("element vertex announces " + std::to_string(data.vertex_count) + " vertices but no vertex properties");

  // Counts are checked against the bytes left before anything is
  // allocated: a header must not make us reserve more than the file holds.
  const std::streamoff body_start = in.tellg();
  in.seekg(0, std::ios::end);
  const auto body_bytes = static_cast<double>(in.tellg() - body_start);
  in.seekg(body_start);
  std::size_t stride = 0;
  for (const auto& p : data.vertex) stride += type_size(p.type);
  const double needed =
      binary ? static_cast<double>(stride) * static_cast<double>(data.vertex_count) +
                   static_cast<double>(face_count) * static_cast<double>(type_size(face.count_type) + 3 * type_size(face.index_type))
             : 2.0 * (static_cast<double>(data.vertex.size()) * static_cast<double>(data.vertex_count) + 4.0 * static_cast<double>(face_count));
  if (needed > body_bytes)
    throw fail("header announces " + std::to_string(data.vertex_count) + " vertices and " + std::to_string(face_count) +
               " faces, but the file holds only " + std::to_string(static_cast<long long>(body_bytes)) + " bytes of data (truncated?)");
  for (auto& p : data.vertex) p.values.resize(data.vertex_count);
  data.faces.resize(face_count);
  if (binary) {
    std::vector<char> buf(stride * data.vertex_count);
    if (!in.read(buf.data(), static_cast<std::streamsize>(buf.size()))) throw fail("file ends inside the vertex data (truncated?)");
    const char* q = buf.data();
    for (std::size_t i = 0; i < data.vertex_count; ++i)
      for (auto& p : data.vertex) {
        p.values[i] = get_value(q, p.type);
        q += type_size(p.type);
      }
    for (std::size_t f = 0; f < face_count; ++f) {
      char tmp[8];
      if (!in.read(tmp, static_cast<std::streamsize>(type_size(face.count_type)))) throw fail("file ends inside the face data (truncated?)");
      const double n = get_value(tmp, face.count_type);
      if (n != 3) throw fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; only triangles are supported");
      for (std::size_t k = 0; k < 3; ++k) {
        if (!in.read(tmp, static_cast<std::streamsize>(type_size(face.index_type)))) throw fail("file ends inside the face data (truncated?)");
        const double v = get_value(tmp, face.index_type);
        if (!(v >= 0 && v < static_cast<double>(data.vertex_count)))
          throw fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " + std::to_string(data.vertex_count));
        data.faces[f][k] = static_cast<std::uint32_t>(v);
      }
    }
  } else {
    for (std::size_t i = 0; i < data.vertex_count; ++i)
      for (auto& p : data.vertex)
        if (!(in >> p.values[i])) throw fail("ASCII vertex data ends early");
    for (std::size_t f = 0; f < face_count; ++f) {
      std::size_t n;
      if (!(in >> n) || n != 3) throw fail("face " + std::to_string(f) + ": only triangles are supported");
      for (std::size_t k = 0; k < 3; ++k) in >> data.faces[f][k];
    }
    if (!in) throw fail("ASCII face data ends early");
  }
  for (std::size_t f = 0; f < face_count; ++f)
    for (std::uint32_t v : data.faces[f])
      if (v >= data.vertex_count) throw fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " + std::to_string(data.vertex_count));
  return data;
}

}  // namespace dp::io
