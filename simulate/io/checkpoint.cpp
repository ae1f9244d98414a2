#include "checkpoint.h"

#include <zlib.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <type_traits>
#include <vector>

#include "atomic_file.h"

namespace dp::io {

static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian and written as the host holds them");

namespace {

constexpr char kMagic[8] = {'D', 'E', 'W', 'P', 'T', 'C', 'K', 'P'};

std::uint32_t crc32_of(const char* data, std::size_t size) {
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes lengths in uInt; checkpoints of large scenes exceed 4 GiB only in pieces.
  while (size > 0) {
    const uInt piece = static_cast<uInt>(std::min<std::size_t>(size, 1u << 30));
    crc = crc32(crc, reinterpret_cast<const Bytef*>(data), piece);
    data += piece;
    size -= piece;
  }
  return static_cast<std::uint32_t>(crc);
}

class ByteWriter {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const char* p = reinterpret_cast<const char*>(&value);
    bytes_.append(p, sizeof(T));
  }
  template <class T>
  void put_array(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void put_vec3s(const std::vector<Vec3>& v) {
    put<std::uint64_t>(v.size());
    for (const Vec3& x : v) {
      put(x.x);
      put(x.y);
      put(x.z);
    }
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  ByteReader(const std::string& bytes, std::size_t end, std::string name) : bytes_(bytes), end_(end), name_(std::move(name)) {}
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> get_array() {
    const std::size_t n = count(sizeof(T));
    std::vector<T> v(n);
    if (n > 0) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
    return v;
  }
  std::vector<Vec3> get_vec3s() {
    const std::size_t n = count(3 * sizeof(float));
    std::vector<Vec3> v(n);
    for (Vec3& x : v) {
      x.x = get<float>();
      x.y = get<float>();
      x.z = get<float>();
    }
    return v;
  }
  bool at_end() const { return at_ == end_; }

 private:
  // An element count that the remaining bytes can hold: a damaged count
  // must not ask for terabytes.
  std::size_t count(std::size_t element_size) {
    const auto n = get<std::uint64_t>();
    if (n > (end_ - at_) / element_size) throw CheckpointCorrupt(name_ + ": array length " + std::to_string(n) + " runs past the end of the file");
    return static_cast<std::size_t>(n);
  }
  const char* take(std::size_t size) {
    if (size > end_ - at_) throw CheckpointCorrupt(name_ + ": truncated");
    const char* p = bytes_.data() + at_;
    at_ += size;
    return p;
  }
  const std::string& bytes_;
  std::size_t at_ = 0, end_;
  std::string name_;
};

void put_ledger(ByteWriter& w, const WaterLedger& l) {
  for (double v : {l.liquid_kg, l.texel_kg, l.vapor_kg, l.initial_kg, l.inflow_gain_kg, l.open_in_kg, l.open_out_kg, l.liquid_to_air_kg,
                   l.texels_to_air_kg, l.texels_to_liquid_kg, l.liquid_out_kg})
    w.put(v);
}
WaterLedger get_ledger(ByteReader& r) {
  WaterLedger l;
  for (double* v : {&l.liquid_kg, &l.texel_kg, &l.vapor_kg, &l.initial_kg, &l.inflow_gain_kg, &l.open_in_kg, &l.open_out_kg,
                    &l.liquid_to_air_kg, &l.texels_to_air_kg, &l.texels_to_liquid_kg, &l.liquid_out_kg})
    *v = r.get<double>();
  return l;
}

void put_state(ByteWriter& w, const SimulationState& s) {
  w.put(s.steps);
  w.put(s.settling_steps);
  w.put(s.time);
  w.put(s.last_max_acceleration);
  w.put(s.converged_step_limit);
  w.put(s.emitted_particles);
  w.put(s.left_domain_particles);
  w.put(s.left_domain_units);
  w.put(s.liquid_to_air_lo);
  w.put(s.liquid_to_air_hi);
  w.put(s.texels_to_air_lo);
  w.put(s.texels_to_air_hi);
  put_ledger(w, s.initial_water);
  const LiquidState& l = s.liquid;
  w.put_vec3s(l.position);
  w.put_vec3s(l.velocity);
  w.put_array(l.temperature);
  w.put_array(l.mass_units);
  w.put_array(l.id);
  w.put_array(l.density);
  w.put_array(l.pressure);
  w.put_array(l.surface_area);
  w.put(l.next_id);
  w.put_array(s.rigid_temperature);
  w.put<std::uint64_t>(s.surfaces.size());
  for (const SurfaceState& t : s.surfaces) {
    w.put_array(t.mass_units);
    w.put_array(t.temperature);
    w.put_array(t.wetting);
  }
  w.put<std::uint8_t>(s.has_air ? 1 : 0);
  if (!s.has_air) return;
  const AirGridState& a = s.air;
  w.put_array(a.u);
  w.put_array(a.v);
  w.put_array(a.w);
  w.put_array(a.temperature_excess);
  w.put_array(a.vapor);
  w.put_array(a.pressure);
  w.put_array(a.kind);
  for (double v : {a.ledger.initial, a.ledger.inflow_gain, a.ledger.open_in, a.ledger.open_out, a.ledger.exchanged}) w.put(v);
}

SimulationState get_state(ByteReader& r) {
  SimulationState s;
  s.steps = r.get<std::int64_t>();
  s.settling_steps = r.get<std::int64_t>();
  s.time = r.get<double>();
  s.last_max_acceleration = r.get<float>();
  s.converged_step_limit = r.get<float>();
  s.emitted_particles = r.get<std::uint64_t>();
  s.left_domain_particles = r.get<std::uint64_t>();
  s.left_domain_units = r.get<std::uint64_t>();
  s.liquid_to_air_lo = r.get<std::uint64_t>();
  s.liquid_to_air_hi = r.get<std::int64_t>();
  s.texels_to_air_lo = r.get<std::uint64_t>();
  s.texels_to_air_hi = r.get<std::int64_t>();
  s.initial_water = get_ledger(r);
  LiquidState& l = s.liquid;
  l.position = r.get_vec3s();
  l.velocity = r.get_vec3s();
  l.temperature = r.get_array<float>();
  l.mass_units = r.get_array<std::uint32_t>();
  l.id = r.get_array<std::uint32_t>();
  l.density = r.get_array<float>();
  l.pressure = r.get_array<float>();
  l.surface_area = r.get_array<float>();
  l.next_id = r.get<std::uint32_t>();
  s.rigid_temperature = r.get_array<float>();
  const auto surfaces = r.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < surfaces; ++i) {
    SurfaceState t;
    t.mass_units = r.get_array<std::uint64_t>();
    t.temperature = r.get_array<float>();
    t.wetting = r.get_array<float>();
    s.surfaces.push_back(std::move(t));
  }
  s.has_air = r.get<std::uint8_t>() != 0;
  if (!s.has_air) return s;
  AirGridState& a = s.air;
  a.u = r.get_array<float>();
  a.v = r.get_array<float>();
  a.w = r.get_array<float>();
  a.temperature_excess = r.get_array<float>();
  a.vapor = r.get_array<double>();
  a.pressure = r.get_array<float>();
  a.kind = r.get_array<std::uint8_t>();
  for (double* v : {&a.ledger.initial, &a.ledger.inflow_gain, &a.ledger.open_in, &a.ledger.open_out, &a.ledger.exchanged}) *v = r.get<double>();
  return s;
}

}  // namespace

std::uint64_t scene_document_hash(const nlohmann::json& document) {
  const std::string text = document.dump();
  return (static_cast<std::uint64_t>(text.size() & 0xffffffffu) << 32) | crc32_of(text.data(), text.size());
}

std::string encode_checkpoint(const Checkpoint& c) {
  ByteWriter w;
  w.bytes().append(kMagic, sizeof kMagic);
  w.put(kCheckpointVersion);
  w.put(c.scene_hash);
  w.put<std::int32_t>(c.frame);
  put_state(w, c.state);
  w.put(crc32_of(w.bytes().data(), w.bytes().size()));
  return std::move(w.bytes());
}

Checkpoint decode_checkpoint(const std::string& bytes, const std::string& name) {
  const std::size_t header = sizeof kMagic + sizeof(std::uint32_t);
  if (bytes.size() < header + sizeof(std::uint32_t)) throw CheckpointCorrupt(name + ": truncated (" + std::to_string(bytes.size()) + " bytes)");
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) throw CheckpointCorrupt(name + ": not a dewpoint checkpoint (wrong magic)");
  std::uint32_t version;
  std::memcpy(&version, bytes.data() + sizeof kMagic, sizeof version);
  if (version != kCheckpointVersion)
    throw CheckpointCorrupt(name + ": checkpoint version " + std::to_string(version) + ", this dewpoint reads version " +
                            std::to_string(kCheckpointVersion));
  const std::size_t body = bytes.size() - sizeof(std::uint32_t);
  std::uint32_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  if (stored != crc32_of(bytes.data(), body)) throw CheckpointCorrupt(name + ": checksum mismatch (truncated or damaged)");
  ByteReader r(bytes, body, name);
  r.get<std::uint64_t>();  // magic, checked above
  r.get<std::uint32_t>();  // version
  Checkpoint c;
  c.scene_hash = r.get<std::uint64_t>();
  c.frame = r.get<std::int32_t>();
  c.state = get_state(r);
  if (!r.at_end()) throw CheckpointCorrupt(name + ": unexpected bytes after the state");
  return c;
}

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint) {
  const std::string bytes = encode_checkpoint(checkpoint);
  write_atomically(file, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CheckpointCorrupt(file.string() + ": cannot open");
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw CheckpointCorrupt(file.string() + ": read error");
  return decode_checkpoint(bytes, file.string());
}

}  // namespace dp::io
