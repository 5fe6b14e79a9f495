// What the SSAO passes share (ssao_kernel.cpp fills it, std140).
#ifndef LG_SSAO_CONSTANTS_GLSL
#define LG_SSAO_CONSTANTS_GLSL

#include "nodes/common/shaders/camera.glsl"

layout(std140, binding = 0) uniform Constants {
  Camera camera;
  vec4 settings;  // radius (m), bias (m), near plane, unused
  uvec4 counts;   // samples, frame index
};

// Reversed-Z infinite projection: device depth = near / linear depth.
float linear_depth(float device_depth) {
  return device_depth > 0.0 ? settings.z / device_depth : 1e8;
}

#endif
