// What the G-buffer pass knows of one draw (std430; gbuffer_kernel.cpp fills it).
#ifndef LG_GBUFFER_DRAW_GLSL
#define LG_GBUFFER_DRAW_GLSL

#include "nodes/common/shaders/camera.glsl"

struct Draw {
  mat4 world;
  mat4 previous_world;
  mat4 normal_matrix;  // inverse transpose of world's upper 3x3
  vec4 base_color;     // linear RGBA, multiplies the texture
  vec4 material;       // perceptual roughness, metalness
};

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
layout(std430, binding = 1) readonly buffer Draws { Draw draws[]; };
layout(push_constant) uniform DrawIndex { uint draw_index; };

#endif
