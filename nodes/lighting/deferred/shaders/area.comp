#version 460
#extension GL_GOOGLE_include_directive : require
// Sphere, tube and rectangle lights (area_lights.glsl), added onto the output.
#include "nodes/lighting/deferred/shaders/area_lights.glsl"
#include "nodes/lighting/deferred/shaders/surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 5, rgba16f) uniform image2D color;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(color)))) return;
  Surface s;
  if (!read_surface(texel, s)) return;
  vec4 before = imageLoad(color, texel);
  imageStore(color, texel, vec4(before.rgb + finite_or_zero(area_radiance(s)), before.a));
}
