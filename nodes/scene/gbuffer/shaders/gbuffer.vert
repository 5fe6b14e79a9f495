#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer vertex stage of textured or vertex-coloured draws: gbuffer_vertex.glsl.
#define LG_MATERIAL_MAPS
#include "nodes/scene/gbuffer/shaders/gbuffer_vertex.glsl"
