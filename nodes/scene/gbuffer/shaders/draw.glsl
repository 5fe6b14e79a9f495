// What the G-buffer pass knows of one draw (std430; draw_constants.cpp fills it).
#ifndef LG_GBUFFER_DRAW_GLSL
#define LG_GBUFFER_DRAW_GLSL

#include "nodes/common/shaders/camera.glsl"

// The material's textures, in the order of MaterialTexture (draw_constants.h).
#define LG_BASE_COLOR_MAP 0
#define LG_METALLIC_ROUGHNESS_MAP 1
#define LG_NORMAL_MAP 2
#define LG_OCCLUSION_MAP 3
#define LG_EMISSIVE_MAP 4

struct Draw {
  mat4 world;
  mat4 previous_world;
  mat4 normal_matrix;  // inverse transpose of world's upper 3x3
  vec4 base_color;     // linear RGBA, multiplies the texture and the vertex colour
  vec4 material;       // perceptual roughness, metalness, normal scale (0: no normal map), occlusion strength
  vec4 alpha;          // x: alpha cutoff of MASK materials
  vec4 emissive;       // rgb: emitted radiance, multiplies the emissive texture
  // Per texture two rows of its 2x3 uv transform; the first row's w is its texcoord set, the
  // second's 1 where the material has the texture.
  vec4 uv_transforms[10];
};

// A fragment stage that reads a larger block at binding 0 starting with the camera
// (scene.forward_transparent: lighting.deferred's constants) defines LG_CAMERA_DECLARED; std140
// puts the camera at offset 0 in both, so the vertex stage's view of the buffer stays right.
#ifndef LG_CAMERA_DECLARED
layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
#endif
layout(std430, binding = 1) readonly buffer Draws { Draw draws[]; };
layout(push_constant) uniform DrawIndex { uint draw_index; };

#endif
