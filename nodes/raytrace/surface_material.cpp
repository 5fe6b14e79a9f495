#include "nodes/raytrace/surface_material.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

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

// Texel index i of a row or column `size` long, as the wrap mode maps it.
uint32_t wrap(int64_t i, uint32_t size, TextureWrap mode) {
  const int64_t n = size;
  switch (mode) {
    case TextureWrap::clamp_to_edge:
      return uint32_t(std::clamp<int64_t>(i, 0, n - 1));
    case TextureWrap::mirrored_repeat: {
      const int64_t period = ((i % (2 * n)) + 2 * n) % (2 * n);
      return uint32_t(period < n ? period : 2 * n - 1 - period);
    }
    case TextureWrap::repeat:
      break;
  }
  return uint32_t(((i % n) + n) % n);
}

glm::dvec4 texel(const TextureData& t, uint32_t col, uint32_t row) {
  const uint8_t* p = &t.rgba8[(size_t(row) * t.width + col) * 4];
  if (t.color_space == ColorSpace::srgb) {
    const auto& linear = srgb_to_linear_table();
    return {linear[p[0]], linear[p[1]], linear[p[2]], p[3] / 255.0};
  }
  return glm::dvec4(p[0], p[1], p[2], p[3]) / 255.0;
}

// The uv a texture reference reads: its set, through KHR_texture_transform (the G-buffer's
// uv_transform_rows in nodes/scene/gbuffer/draw_constants.cpp).
glm::dvec2 reference_uv(const TextureRef& ref, const SurfaceTexcoords& at) {
  const glm::dvec2 uv = ref.texcoord == 1 ? at.uv1 : at.uv0;
  const double c = std::cos(ref.rotation), s = std::sin(ref.rotation);
  return {c * ref.scale.x * uv.x + s * ref.scale.y * uv.y + ref.offset.x,
          -s * ref.scale.x * uv.x + c * ref.scale.y * uv.y + ref.offset.y};
}

// The texture `ref` names, or null where there is none.
const TextureData* referenced_texture(const SceneView& view, const TextureRef& ref) {
  return ref.texture < 0 || size_t(ref.texture) >= view.textures.size() ? nullptr : view.textures[ref.texture].get();
}

// The referenced texture's value, or 1 where the material has none.
glm::dvec4 sample_reference(const SceneView& view, const TextureRef& ref, const SurfaceTexcoords& at) {
  const TextureData* texture = referenced_texture(view, ref);
  return texture ? sample_texture(*texture, ref.sampling, reference_uv(ref, at)) : glm::dvec4(1.0);
}

}  // namespace

glm::dvec4 sample_texture(const TextureData& texture, const TextureSampling& sampling, glm::dvec2 uv) {
  if (texture.width == 0 || texture.height == 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::dvec4(1.0);
  const double x = uv.x * texture.width - 0.5, y = uv.y * texture.height - 0.5;
  if (sampling.mag == TextureFilter::nearest)
    return texel(texture, wrap(int64_t(std::floor(x + 0.5)), texture.width, sampling.wrap_u),
                 wrap(int64_t(std::floor(y + 0.5)), texture.height, sampling.wrap_v));
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  glm::dvec4 sum(0.0);
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const uint32_t col = wrap(int64_t(fx) + dx, texture.width, sampling.wrap_u);
      const uint32_t row = wrap(int64_t(fy) + dy, texture.height, sampling.wrap_v);
      sum += (dx ? tx : 1.0 - tx) * (dy ? ty : 1.0 - ty) * texel(texture, col, row);
    }
  return sum;
}

SurfaceMaterial sample_material(const SceneView& view, const DrawItem& draw, const SurfaceTexcoords& at) {
  const PbrMaterial& m = view.material_of(draw);
  const glm::dvec4 base = glm::dvec4(m.base_color) * at.color * sample_reference(view, m.base_color_texture, at);
  const glm::dvec4 metal_rough = sample_reference(view, m.metallic_roughness_texture, at);
  SurfaceMaterial out;
  out.base_color = glm::clamp(glm::dvec3(base), 0.0, 1.0);
  out.roughness = std::clamp(double(m.roughness) * metal_rough.g, 0.0, 1.0);
  out.metalness = std::clamp(double(m.metalness) * metal_rough.b, 0.0, 1.0);
  out.emissive = glm::dvec3(m.emissive) * glm::dvec3(sample_reference(view, m.emissive_texture, at));
  return out;
}

double coverage_alpha(const PbrMaterial& m, const TextureData* texture, const SurfaceTexcoords& at) {
  const double alpha = double(m.base_color.a) * at.color.a;
  return texture
             ? alpha * sample_texture(*texture, m.base_color_texture.sampling, reference_uv(m.base_color_texture, at)).a
             : alpha;
}

glm::dvec3 mapped_normal(const SceneView& view, const DrawItem& draw, const SurfaceTexcoords& at, glm::dvec3 n,
                         glm::dvec4 tangent) {
  const PbrMaterial& m = view.material_of(draw);
  const TextureData* texture = referenced_texture(view, m.normal_texture);
  if (!texture) return n;
  glm::dvec3 t = glm::dvec3(tangent) - n * glm::dot(n, glm::dvec3(tangent));
  if (!(glm::dot(t, t) > 1e-12)) return n;  // no usable frame: the interpolated normal, as the raster
  t = glm::normalize(t);
  const glm::dvec3 b = glm::cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
  glm::dvec3 texel =
      glm::dvec3(sample_texture(*texture, m.normal_texture.sampling, reference_uv(m.normal_texture, at)));
  texel = texel * 2.0 - 1.0;
  const double scale = m.normal_scale;
  const glm::dvec3 mapped = t * (texel.x * scale) + b * (texel.y * scale) + n * texel.z;
  return glm::dot(mapped, mapped) > 1e-12 ? glm::normalize(mapped) : n;
}

}  // namespace lg
