#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's ambient occlusion (r8) at resolution_scale 1/k below 1 back to the G-buffer's
// resolution, as its irradiance (upsample_pass.glsl); the sky is unoccluded, as occlusion.gtao
// writes it.
#define LG_UPSAMPLE_FORMAT r8
#define LG_UPSAMPLE_SKY vec4(1.0)
#include "nodes/gi/irradiance_volume/shaders/upsample_pass.glsl"
