#include "nodes/gi/reflection_capture/reflection_probe_buffer.h"

#include <glm/matrix.hpp>
#include <stdexcept>
#include <string>

namespace lg {
namespace {

glm::vec4 shape_size(ProbeShape shape, glm::vec3 extent, float radius) {
  return shape == ProbeShape::box ? glm::vec4(extent, 0.0f) : glm::vec4(radius, radius, radius, 0.0f);
}

}  // namespace

std::vector<GpuReflectionProbe> pack_reflection_probes(const SceneView& scene, const std::string& who) {
  if (scene.reflection_probes.size() > kMaxReflectionProbes)
    throw std::invalid_argument(who + ": the scene has " + std::to_string(scene.reflection_probes.size()) +
                                " reflection probes, more than the " + std::to_string(kMaxReflectionProbes) +
                                " the lookup takes");
  std::vector<GpuReflectionProbe> out(kMaxReflectionProbes, GpuReflectionProbe{});
  for (size_t i = 0; i < scene.reflection_probes.size(); ++i) {
    const ReflectionProbeData& data = scene.reflection_probes[i];
    const ReflectionProbe& p = data.probe;
    GpuReflectionProbe& g = out[i];
    g.to_world = data.world;
    g.to_local = glm::inverse(data.world);
    g.influence = shape_size(p.influence, p.extent, p.radius);
    g.influence.w = p.blend;
    g.proxy = shape_size(p.proxy, p.proxy_extent, p.proxy_radius);
    g.proxy_offset = glm::vec4(p.proxy_offset, 0.0f);
    g.shapes = glm::uvec4(p.influence == ProbeShape::sphere ? 1u : 0u, p.proxy == ProbeShape::sphere ? 1u : 0u, 0u, 0u);
  }
  return out;
}

}  // namespace lg
