#include "nodes/raytrace/surface_material.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>

namespace lg {
namespace {

// sRGB's transfer function inverted, for each 8-bit code.
const std::array<double, 256>& srgb_to_linear_table() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[i] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    return t;
  }();
  return table;
}

uint32_t wrap(int64_t i, uint32_t size) {
  return uint32_t(((i % int64_t(size)) + size) % size);
}

}  // namespace

glm::dvec3 sample_srgb_texture(const TextureData& texture, glm::dvec2 uv) {
  if (texture.width == 0 || texture.height == 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::dvec3(1.0);
  const auto& linear = srgb_to_linear_table();
  const double x = uv.x * texture.width - 0.5, y = uv.y * texture.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  glm::dvec3 sum(0.0);
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const uint32_t col = wrap(int64_t(fx) + dx, texture.width), row = wrap(int64_t(fy) + dy, texture.height);
      const uint8_t* texel = &texture.rgba8[(size_t(row) * texture.width + col) * 4];
      const double weight = (dx ? tx : 1.0 - tx) * (dy ? ty : 1.0 - ty);
      sum += weight * glm::dvec3(linear[texel[0]], linear[texel[1]], linear[texel[2]]);
    }
  return sum;
}

SurfaceMaterial sample_material(const SceneView& view, const DrawItem& draw, glm::dvec2 uv) {
  const PbrMaterial& m = view.material_of(draw);
  glm::dvec3 color(m.base_color);
  const int texture = m.base_color_texture.texture;
  if (texture >= 0 && size_t(texture) < view.textures.size()) color *= sample_srgb_texture(*view.textures[texture], uv);
  SurfaceMaterial out;
  out.base_color = glm::clamp(color, 0.0, 1.0);
  out.roughness = std::clamp(double(m.roughness), 0.0, 1.0);
  out.metalness = std::clamp(double(m.metalness), 0.0, 1.0);
  out.emissive = glm::dvec3(m.emissive);
  return out;
}

}  // namespace lg
