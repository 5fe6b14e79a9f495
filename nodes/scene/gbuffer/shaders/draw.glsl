// The G-buffer pass's bindings: the camera, every draw (draw_data.glsl) and which one this is.
#ifndef LG_GBUFFER_DRAW_GLSL
#define LG_GBUFFER_DRAW_GLSL

#include "nodes/common/shaders/camera.glsl"
#include "nodes/scene/gbuffer/shaders/draw_data.glsl"

// A fragment stage that reads a larger block at binding 0 starting with the camera
// (scene.forward_transparent: lighting.deferred's constants) defines LG_CAMERA_DECLARED; std140
// puts the camera at offset 0 in both, so the vertex stage's view of the buffer stays right.
#ifndef LG_CAMERA_DECLARED
layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
#endif
layout(std430, binding = 1) readonly buffer Draws { Draw draws[]; };
layout(push_constant) uniform DrawIndex { uint draw_index; };

#ifdef LG_DRAW_BLOCK
// The G-buffer's stages read their draw as a uniform block (gbuffer_kernel.cpp binds each
// draw's range of a buffer of them): lavapipe loads a storage buffer one lane at a time even
// where every lane reads the same draw (docs/lavapipe-costs.md); draws[draw_index] was about
// half of the G-buffer pass. gbuffer.vert, the textured vertex stage without it, serves
// scene.forward_transparent and the reflection capture, which bind only the storage buffer.
layout(std140, binding = 6) uniform DrawBlock { Draw this_draw; };
#endif

#endif
