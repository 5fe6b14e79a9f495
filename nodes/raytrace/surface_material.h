// A draw's material at one surface point, read as the G-buffer reads it (nodes/scene/gbuffer),
// so that ray tracers shade the surfaces the raster path shows: the glTF metal-rough factors
// times their textures (each through its texcoord set, KHR_texture_transform and sampler's
// wrap modes, level 0 with the magnification filter: a ray has no pixel footprint; colour
// textures decoded from sRGB) and the vertex colours, clamped to [0, 1] like the G-buffer's
// channels; the normal texture in the tangent frame the G-buffer builds; the alpha the
// G-buffer's MASK test compares (alpha_coverage.h lets rays through where it is below).
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

// The alpha the G-buffer's MASK test compares with alphaCutoff: the base colour factor's x the
// vertex colour's x the base colour texture's (`texture`, null where the material has none).
double coverage_alpha(const PbrMaterial& material, const TextureData* texture, const SurfaceTexcoords& at);

// The shading normal with the material's normal texture applied as the G-buffer applies it
// (nodes/scene/gbuffer/shaders/gbuffer_surface.glsl): `normal` the unit interpolated normal of
// the front side, `tangent` the interpolated world tangent with the bitangent's sign in w. Without
// a normal texture, or with no usable tangent frame (zero tangent, tangent along the normal),
// `normal` itself.
glm::dvec3 mapped_normal(const SceneView& view, const DrawItem& draw, const SurfaceTexcoords& at, glm::dvec3 normal,
                         glm::dvec4 tangent);

// The texture at `uv` (texel centres at (i + 0.5) / size) with the sampler's wrap modes and
// magnification filter, decoded to linear as its colour space says.
glm::dvec4 sample_texture(const TextureData& texture, const TextureSampling& sampling, glm::dvec2 uv);

}  // namespace lg
