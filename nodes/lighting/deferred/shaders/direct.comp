#version 460
#extension GL_GOOGLE_include_directive : require
// Directional, point and spot lights (direct_lights.glsl) on every G-buffer texel; writes (and
// so clears) the node's output.
#include "nodes/lighting/deferred/shaders/direct_lights.glsl"
#include "nodes/lighting/deferred/shaders/surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 5, rgba16f) uniform writeonly image2D color;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(color)))) return;
  Surface s;
  vec3 radiance = read_surface(texel, s) ? direct_radiance(s) : vec3(0.0);
  imageStore(color, texel, vec4(finite_or_zero(radiance), 1.0));
}
