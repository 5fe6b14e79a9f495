// A draw's material at one surface point, read as the G-buffer reads it (nodes/scene/gbuffer),
// so that ray tracers shade the surfaces the raster path shows: the base colour factor times
// the base-colour texture (sRGB decoded, bilinear, repeating), clamped to [0, 1] like the
// G-buffer's channels, and the constant roughness, metalness and emission.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

struct SurfaceMaterial {
  glm::dvec3 base_color{1.0};
  double roughness = 0.5;  // perceptual
  double metalness = 0.0;
  glm::dvec3 emissive{0.0};  // radiance
};

SurfaceMaterial sample_material(const SceneView& view, const DrawItem& draw, glm::dvec2 uv);

// The texture's colour at `uv` (texel centres at (i + 0.5) / size), bilinear with repeat
// wrapping, decoded from sRGB to linear; rgb only.
glm::dvec3 sample_srgb_texture(const TextureData& texture, glm::dvec2 uv);

}  // namespace lg
