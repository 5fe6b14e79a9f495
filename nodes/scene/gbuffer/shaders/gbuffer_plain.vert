#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer vertex stage of draws without textures or vertex colours: gbuffer_vertex.glsl.
#include "nodes/scene/gbuffer/shaders/gbuffer_vertex.glsl"
