// The scene parser must answer any bytes with a SceneError naming the file
// and key, never a crash, a hang or another exception type.
#include "fuzz_input_file.h"
#include "scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = dp::fuzz::write_input("scene.json", data, size);
  try {
    dp::io::load_scene(file);
  } catch (const dp::io::SceneError&) {
  }
  return 0;
}
