// The SPIR-V of the env nodes' shaders (lg_embed_shaders in nodes/env/CMakeLists.txt), looked
// up by source path: "nodes/env/sky/shaders/sky.comp".
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "runtime/gpu/embedded_shader.h"

namespace lg {

std::span<const EmbeddedShader> env_shaders();  // generated

inline std::span<const uint32_t> env_shader(std::string_view path) {
  return find_shader(env_shaders(), path);
}

}  // namespace lg
