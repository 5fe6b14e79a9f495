// What occlusion.baked's drawing pass knows of each draw's bake (std430; baked_kernel.cpp fills
// it), beside the G-buffer pass's camera and draws (nodes/scene/gbuffer/shaders/draw.glsl).
#ifndef LG_BAKED_DRAW_GLSL
#define LG_BAKED_DRAW_GLSL

#include "nodes/scene/gbuffer/shaders/draw.glsl"

const uint kNoBake = 0u;
const uint kVertexBake = 1u;  // vertex_occlusion[vertex_base + vertex index]
const uint kTexelBake = 2u;   // lightmap_texels[lightmap_base + row * lightmap_size + column], uv = lightmap UV

struct BakedDraw {
  uint kind;
  uint vertex_base;
  uint lightmap_base;
  uint lightmap_size;
  mat4 lightmap_to_world;  // texel: the normal matrix times the lightmap's bake-to-mesh matrix
};

layout(std430, binding = 2) readonly buffer BakedDraws { BakedDraw baked_draws[]; };
// xyz the bent normal in the mesh's space, w k_A.
layout(std430, binding = 3) readonly buffer VertexOcclusion { vec4 vertex_occlusion[]; };
layout(std430, binding = 4) readonly buffer LightmapTexels { vec4 lightmap_texels[]; };

#endif
