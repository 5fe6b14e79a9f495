// The G-buffer's normal encoding on the CPU, the twin of nodes/common/shaders/gbuffer.glsl's
// encode_normal and decode_normal: for references that read a G-buffer back and tests that
// write one.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lg {

// -1, 0 and 1 land exactly on steps 0, 511 and 1022 of the rgb10a2 channel.
inline glm::dvec3 encode_gbuffer_normal(const glm::dvec3& n) {
  return (n * 511.0 + 511.0) / 1023.0;
}

// `rgba` as stored; a zero-length normal decodes to +z.
inline glm::dvec3 decode_gbuffer_normal(const float* rgba) {
  const glm::dvec3 n = (glm::dvec3(rgba[0], rgba[1], rgba[2]) * 1023.0 - 511.0) / 511.0;
  const double length = glm::length(n);
  return length > 1e-3 ? n / length : glm::dvec3(0.0, 0.0, 1.0);
}

}  // namespace lg
