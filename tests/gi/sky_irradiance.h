// The sky's irradiance at a normal from the graph output "sh.sh" (env.sh_project, order 2,
// cosine-convolved, [r, g, b, w] a coefficient), as the nodes that take the SH evaluate it: for
// the tests of gi.lpv's and gi.voxel's sky.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>
#include <glm/vec3.hpp>
#include <vector>

#include "api/renderer.h"
#include "nodes/env/common/sh_basis.h"

namespace lg::test {

// Green channel, W/m^2, `n` unit: each band's share (0, 1 and 2), unclamped.
inline std::array<double, 3> sky_bands_green(Renderer& renderer, glm::dvec3 n) {
  const std::vector<std::byte> bytes = renderer.executor().read_buffer("sh.sh");
  std::vector<float> sh(bytes.size() / sizeof(float));
  std::memcpy(sh.data(), bytes.data(), sh.size() * sizeof(float));
  double y[9];
  sh_evaluate(2, n, y);
  std::array<double, 3> bands{};
  for (int k = 0; k < 9 && 4 * k + 1 < int(sh.size()); ++k) bands[k < 1 ? 0 : k < 4 ? 1 : 2] += sh[4 * k + 1] * y[k];
  return bands;
}

// The whole irradiance, negative ringing clamped to 0 as the nodes clamp it.
inline double sky_irradiance_green(Renderer& renderer, glm::dvec3 n) {
  const std::array<double, 3> bands = sky_bands_green(renderer, n);
  return std::max(bands[0] + bands[1] + bands[2], 0.0);
}

}  // namespace lg::test
