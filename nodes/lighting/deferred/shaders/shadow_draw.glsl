// What the depth passes from a light (shadow map and local shadow atlas) bind: every draw
// (nodes/scene/gbuffer/shaders/draw_data.glsl), the view's matrix and which draw this is.
#ifndef LG_SHADOW_DRAW_GLSL
#define LG_SHADOW_DRAW_GLSL

#include "nodes/scene/gbuffer/shaders/draw_data.glsl"

layout(std430, binding = 0) readonly buffer Draws { Draw draws[]; };
layout(push_constant) uniform Push {
  mat4 shadow_from_world;
  uint draw_index;
};

#endif
