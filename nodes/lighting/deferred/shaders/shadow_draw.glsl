// What the depth passes from a light (shadow map and local shadow atlas) bind: the draw
// (nodes/scene/gbuffer/shaders/draw_data.glsl) as a uniform block, its range of a buffer of
// every draw's bound per draw (draw_constants.h's draw_blocks: lavapipe loads a storage buffer
// one lane at a time, so draws[draw_index] cost a third of the shadow map's pass), and the
// view's matrix.
#ifndef LG_SHADOW_DRAW_GLSL
#define LG_SHADOW_DRAW_GLSL

#include "nodes/scene/gbuffer/shaders/draw_data.glsl"

layout(std140, binding = 0) uniform DrawBlock { Draw this_draw; };
layout(push_constant) uniform Push { mat4 shadow_from_world; };

#endif
