#version 460
#extension GL_GOOGLE_include_directive : require
// Depth from a light for alpha-tested draws (shadow_masked.frag): shadow_vertex.glsl with uvs and alpha.
#define LG_ALPHA_TEST
#include "nodes/lighting/deferred/shaders/shadow_vertex.glsl"
