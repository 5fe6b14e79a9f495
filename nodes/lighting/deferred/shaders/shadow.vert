#version 460
#extension GL_GOOGLE_include_directive : require
// Depth from a light for opaque draws: positions only (shadow_vertex.glsl).
#include "nodes/lighting/deferred/shaders/shadow_vertex.glsl"
