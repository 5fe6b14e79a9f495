#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer fragment stage of alphaMode MASK materials: gbuffer_surface.glsl with its alpha test.
#define LG_MATERIAL_MAPS
#define LG_ALPHA_MASK
#include "nodes/scene/gbuffer/shaders/gbuffer_surface.glsl"
