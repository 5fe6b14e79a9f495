// A draw's material at one surface point, read as the G-buffer reads it (nodes/scene/gbuffer),
// so that ray tracers shade the surfaces the raster path shows: the glTF metal-rough factors
// times their textures (each through its texcoord set, KHR_texture_transform and sampler's
// wrap modes, level 0 with the magnification filter: a ray has no pixel footprint; colour
// textures decoded from sRGB) and the vertex colours, clamped to [0, 1] like the G-buffer's
// channels. Not read yet: the normal texture, alpha and double-sidedness (every surface is
// two-sided and opaque to the ray tracers).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

struct SurfaceMaterial {
  glm::dvec3 base_color{1.0};
  double roughness = 0.5;  // perceptual
  double metalness = 0.0;
  glm::dvec3 emissive{0.0};  // radiance
};

// What the mesh gives the material at the point: both texcoord sets and the vertex colour.
struct SurfaceTexcoords {
  glm::dvec2 uv0{0.0}, uv1{0.0};
  glm::dvec4 color{1.0};
};

SurfaceMaterial sample_material(const SceneView& view, const DrawItem& draw, const SurfaceTexcoords& at);

// The texture at `uv` (texel centres at (i + 0.5) / size) with the sampler's wrap modes and
// magnification filter, decoded to linear as its colour space says.
glm::dvec4 sample_texture(const TextureData& texture, const TextureSampling& sampling, glm::dvec2 uv);

}  // namespace lg
