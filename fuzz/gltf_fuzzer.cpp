// libFuzzer harness: a glTF 2.0 asset, binary (.glb, the input starts with "glTF") or JSON
// (.gltf, buffers and images as data URIs; files it names are missing).
#include "fuzz/fuzz_input.h"
#include "fuzz/mesh_world.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input = lg::fuzz::as_text(data, size);
  const lg::fuzz::InputFile file(input.starts_with("glTF") ? "asset.glb" : "asset.gltf", input);
  lg::fuzz::load_mesh_world(file.path());
  return 0;
}
