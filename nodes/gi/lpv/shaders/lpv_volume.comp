#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's optional volume output (a debug view: `render --dump`, the inspector), one invocation
// per texel of the grid x grid x grid output: rgb the mean over all normals of the irradiance
// the summed light gives, per channel, W/m^2, a: 1 in the grid's cells, 0 in the texels past its
// counts (the grid covers the box's longest side; the shorter ones get fewer cells). With
// lpv_store.comp's radiance L = sum c_i Y_i, E averaged over the normals is a quarter of the
// radiance's integral over the sphere, c_0 Y_0 4 pi / 4 = c_0 sqrt(pi) / 2: the SH L0 term.
// With the sky linked, the sky's light at the cell (lpv_sky.comp's images, its radiance SH times
// the cell's openness, divided by it as the lookup does; not read without the sky, kAddSky, as the
// lookup) is added the same way, so the view holds all the light the lookup reads.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler3D sum_red;  // lpv_store.comp's images, texelFetch only
layout(binding = 2) uniform sampler3D sum_green;
layout(binding = 3) uniform sampler3D sum_blue;
layout(binding = 4, rgba16f) uniform writeonly image3D volume;
layout(binding = 5) uniform sampler3D sky_red;  // lpv_sky.comp's images, texelFetch only
layout(binding = 6) uniform sampler3D sky_green;
layout(binding = 7) uniform sampler3D sky_blue;
layout(binding = 8) uniform sampler3D sky_openness;
layout(constant_id = 0) const int kAddSky = 1;

void main() {
  ivec3 size = imageSize(volume);
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  ivec3 c = ivec3(id.x, id.y % size.y, id.y / size.y);
  if (any(greaterThanEqual(c, size))) return;
  if (!lpv_inside(c)) {
    imageStore(volume, c, vec4(0.0));
    return;
  }
  vec3 l0 = vec3(texelFetch(sum_red, c, 0).x, texelFetch(sum_green, c, 0).x, texelFetch(sum_blue, c, 0).x);
  if (kAddSky != 0) {
    vec3 sky = vec3(texelFetch(sky_red, c, 0).x, texelFetch(sky_green, c, 0).x, texelFetch(sky_blue, c, 0).x);
    l0 += sky / max(texelFetch(sky_openness, c, 0).r, 1e-3);
  }
  imageStore(volume, c, vec4(max(l0, vec3(0.0)) * kCosineY00, 1.0));  // c_0 sqrt(pi) / 2 (above)
}
