#version 460
#extension GL_GOOGLE_include_directive : require
// The raster capture's fragment stage of alphaMode MASK materials: capture_surface.glsl with its alpha test.
#define LG_ALPHA_MASK
#include "nodes/gi/reflection_capture/shaders/capture_surface.glsl"
