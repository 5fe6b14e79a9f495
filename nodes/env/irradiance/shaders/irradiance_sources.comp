#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1 of env.irradiance: the environment as lights for irradiance.comp, a grid of S x S a
// face (S the sources image's height), light (i, j) of face f at (2i, j, f) its direction and at
// (2i + 1, j, f) its light (radiance x solid angle), made once per frame rather than once per
// output texel.
// The light is summed over the texels of mip `fine_mip` under it (the F x F face split into S
// ranges a side, i F / S to (i + 1) F / S, so every texel counts once whether or not S divides F), and its direction is
// their luminance-weighted mean, kept unnormalised in the light's scale: since n.l is linear in
// l, n . sum(w_k l_k) is the exact cosine-weighted sum of the fine texels for any n that all of
// them face, and for grey light exact in colour too. A sun in a coarse texel then lights along
// its own direction, not the texel's centre (grace at a 16^2 source: 2.3% -> see the bench).
// Non-finite texels count as 0. An image, not a buffer: on lavapipe a texel fetch is several
// times cheaper than a storage-buffer read.
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray env;  // every mip of the six faces
layout(binding = 1, rgba32f) uniform writeonly image2DArray sources;
layout(push_constant) uniform Push {
  int fine_mip;
};

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  const int face = int(gl_GlobalInvocationID.z);
  const int size = imageSize(sources).y, fine_size = textureSize(env, fine_mip).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  const ivec2 first = texel * fine_size / size, last = (texel + 1) * fine_size / size;  // last excluded
  vec3 light = vec3(0.0), moment = vec3(0.0);  // sum w L, sum w lum(L) l
  float luminance = 0.0;                       // sum w lum(L)
  for (int y = first.y; y < last.y; ++y)
    for (int x = first.x; x < last.x; ++x) {
      const ivec2 fine = ivec2(x, y);
      vec3 radiance = texelFetch(env, ivec3(fine, face), fine_mip).rgb;
      if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0);
      const vec3 w_radiance = radiance * cube_texel_solid_angle(fine, fine_size);
      const float w_luminance = dot(w_radiance, vec3(0.2126, 0.7152, 0.0722));
      light += w_radiance;
      luminance += w_luminance;
      moment += w_luminance * cube_direction(face, (vec2(fine) + 0.5) / float(fine_size));
    }
  // Direction d with |d| = |moment| / luminance (1 for one fine texel, less for a spread one):
  // n.d x light is then n.moment x light / luminance. Black texels: the centre, no light.
  const vec3 centre = cube_direction(face, (vec2(texel) + 0.5) / float(size));
  const vec3 direction = luminance > 0.0 ? moment / luminance : centre;
  imageStore(sources, ivec3(2 * texel.x, texel.y, face), vec4(direction, 0.0));
  imageStore(sources, ivec3(2 * texel.x + 1, texel.y, face), vec4(light, 0.0));
}
