#version 460
#extension GL_GOOGLE_include_directive : require
// The raster capture's fragment stage of opaque materials: capture_surface.glsl.
#include "nodes/gi/reflection_capture/shaders/capture_surface.glsl"
