// A shader compiled from GLSL to SPIR-V at build time and embedded in the binary. The tables
// come from lg_embed_shaders() in cmake/EmbedShaders.cmake, one function per library.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace lg {

struct EmbeddedShader {
  std::string_view path;  // the GLSL file relative to the source root: "nodes/post/bloom/downsample.comp"
  std::span<const uint32_t> spirv;
};

// The SPIR-V of the shader at `path`; throws GpuError listing the table when it is not there.
std::span<const uint32_t> find_shader(std::span<const EmbeddedShader> shaders, std::string_view path);

}  // namespace lg
