// The PLY reader (particle frames, rigid particles, liquid meshes) must
// answer any bytes with a runtime_error naming the file, never a crash, an
// out-of-bounds read or an allocation the file's size cannot justify.
#include <stdexcept>

#include "fuzz_input_file.h"
#include "ply.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = dp::fuzz::write_input("frame.ply", data, size);
  try {
    dp::io::read_ply(file);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
