// The frames manifest reader (used by dewpoint-mesh and dewpoint-render)
// must answer any bytes with a runtime_error naming the file and key.
#include <stdexcept>

#include "frames.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dp::fuzz::write_input("manifest.json", data, size);
  try {
    dp::io::read_manifest(dp::fuzz::private_dir());
  } catch (const std::runtime_error&) {
  }
  return 0;
}
