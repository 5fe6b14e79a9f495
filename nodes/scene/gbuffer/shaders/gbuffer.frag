#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer fragment stage of opaque textured or vertex-coloured draws: gbuffer_surface.glsl.
#define LG_MATERIAL_MAPS
#include "nodes/scene/gbuffer/shaders/gbuffer_surface.glsl"
