// libFuzzer harness: an OBJ file with its MTL. The input holds the OBJ text, a NUL byte, then
// the MTL text, written as m.obj and m.mtl side by side (seeds name `mtllib m.mtl`); without a
// NUL it is all OBJ.
#include "fuzz/fuzz_input.h"
#include "fuzz/mesh_world.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input = lg::fuzz::as_text(data, size);
  const size_t split = input.find('\0');
  const lg::fuzz::InputFile mtl("m.mtl", split == std::string_view::npos ? "" : input.substr(split + 1));
  const lg::fuzz::InputFile obj("m.obj", input.substr(0, split));
  lg::fuzz::load_mesh_world(obj.path());
  return 0;
}
