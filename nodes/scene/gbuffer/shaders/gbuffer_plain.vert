#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer vertex stage of draws without textures or vertex colours: gbuffer_vertex.glsl.
#define LG_DRAW_BLOCK
#include "nodes/scene/gbuffer/shaders/gbuffer_vertex.glsl"
