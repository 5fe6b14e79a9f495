// The SPIR-V of every node's shaders, compiled at build time (lg_embed_shaders in
// nodes/CMakeLists.txt) and looked up by source path: "nodes/post/tonemap/shaders/tonemap.comp".
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "runtime/gpu/embedded_shader.h"

namespace lg {

std::span<const EmbeddedShader> node_shaders();  // generated

inline std::span<const uint32_t> node_shader(std::string_view path) {
  return find_shader(node_shaders(), path);
}

}  // namespace lg
