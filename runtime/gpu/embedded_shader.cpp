#include "runtime/gpu/embedded_shader.h"

#include <string>

#include "runtime/gpu/gpu_error.h"

namespace lg {

std::span<const uint32_t> find_shader(std::span<const EmbeddedShader> shaders, std::string_view path) {
  for (const EmbeddedShader& s : shaders)
    if (s.path == path) return s.spirv;
  std::string known;
  for (const EmbeddedShader& s : shaders) known += "\n  " + std::string(s.path);
  throw GpuError("no embedded shader '" + std::string(path) + "'; embedded:" + (known.empty() ? " none" : known));
}

}  // namespace lg
