#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer fragment stage of opaque draws without textures or vertex colours:
// gbuffer_surface.glsl.
#include "nodes/scene/gbuffer/shaders/gbuffer_surface.glsl"
