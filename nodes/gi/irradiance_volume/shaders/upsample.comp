#version 460
#extension GL_GOOGLE_include_directive : require
// gi.irradiance_volume's, gi.lpv's and gi.voxel's upsample of light (rgba16f) at resolution_scale
// 1/k below 1 (upsample_pass.glsl).
#define LG_UPSAMPLE_FORMAT rgba16f
#define LG_UPSAMPLE_SKY vec4(0.0)
#include "nodes/gi/irradiance_volume/shaders/upsample_pass.glsl"
