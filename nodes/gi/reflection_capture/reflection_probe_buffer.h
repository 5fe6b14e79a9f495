// The scene's reflection probes as gi.reflection_capture's lookup reads them: one std140 record
// per probe (shaders/reflection_probes.glsl's ReflectionProbe), at most kMaxReflectionProbes.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

inline constexpr size_t kMaxReflectionProbes = 16;  // LG_MAX_REFLECTION_PROBES

struct GpuReflectionProbe {
  glm::mat4 to_local;
  glm::mat4 to_world;
  glm::vec4 influence;     // xyz: box half sizes or x: radius; w: blend
  glm::vec4 proxy;         // xyz: box half sizes or x: radius
  glm::vec4 proxy_offset;  // xyz
  glm::uvec4 shapes;       // x: influence, y: proxy (0 box, 1 sphere)
};
static_assert(sizeof(GpuReflectionProbe) == 192, "std140 layout of shaders/reflection_probes.glsl");

// kMaxReflectionProbes records, the scene's first and zeros after them; throws
// std::invalid_argument naming `who` when the scene has more probes than that.
std::vector<GpuReflectionProbe> pack_reflection_probes(const SceneView& scene, const std::string& who);

}  // namespace lg
