#include "nodes/env/common/equirect.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lg {

glm::dvec2 equirect_uv(const glm::dvec3& d) {
  const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return {0.5 + std::atan2(d.x, -d.z) / (2 * std::numbers::pi),
          std::acos(std::clamp(d.y / len, -1.0, 1.0)) / std::numbers::pi};
}

glm::dvec3 equirect_direction(const glm::dvec2& uv) {
  const double phi = (uv.x - 0.5) * 2 * std::numbers::pi, theta = uv.y * std::numbers::pi;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

uint64_t sanitize_equirect(std::span<float> rgba, double intensity) {
  uint64_t non_finite = 0;
  for (size_t t = 0; t + 3 < rgba.size(); t += 4) {
    float* texel = &rgba[t];
    const bool finite = std::isfinite(texel[0]) && std::isfinite(texel[1]) && std::isfinite(texel[2]);
    for (int c = 0; c < 3; ++c) texel[c] = finite ? float(texel[c] * intensity) : 0.0f;
    non_finite += finite ? 0 : 1;
  }
  return non_finite;
}

glm::dvec4 sample_equirect(const Equirect& image, const glm::dvec2& uv) {
  const double x = uv.x * image.width - 0.5, y = std::clamp(uv.y * image.height - 0.5, 0.0, image.height - 1.0);
  const int64_t x0 = int64_t(std::floor(x)), y0 = int64_t(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto texel = [&](int64_t i, int64_t j) {
    const int64_t w = image.width, h = image.height;
    i = ((i % w) + w) % w;
    j = std::clamp<int64_t>(j, 0, h - 1);
    const float* p = &image.rgba[(uint64_t(j) * image.width + i) * 4];
    return glm::dvec4(p[0], p[1], p[2], p[3]);
  };
  return (1 - fy) * ((1 - fx) * texel(x0, y0) + fx * texel(x0 + 1, y0)) +
         fy * ((1 - fx) * texel(x0, y0 + 1) + fx * texel(x0 + 1, y0 + 1));
}

CubeImage equirect_to_cube(const Equirect& image, uint32_t face_size, int supersample) {
  CubeImage cube(face_size);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < face_size; ++j)
      for (uint32_t i = 0; i < face_size; ++i) {
        glm::dvec4 sum(0.0);
        for (int b = 0; b < supersample; ++b)
          for (int a = 0; a < supersample; ++a) {
            const double u = (i + (a + 0.5) / supersample) / face_size, v = (j + (b + 0.5) / supersample) / face_size;
            sum += sample_equirect(image, equirect_uv(cube_direction(f, u, v)));
          }
        cube.at(f, i, j) = sum / double(supersample * supersample);
      }
  return cube;
}

}  // namespace lg
