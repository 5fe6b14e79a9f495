#version 460
#extension GL_GOOGLE_include_directive : require
// occlusion.gtao's upsample at resolution_scale 1/k below 1: the denoised, accumulated occlusion
// and the bent normals of the horizon grid brought back to the G-buffer's resolution, both with
// one set of depth-guided weights (joint_upsample.glsl), so occlusion does not leak across a
// silhouette. One invocation per grid texel writes its block of k x k pixels. The guide's
// surfaces come with the occlusion (ao_guide.glsl): two fetches a tap, not four. Each pixel
// fetches its depth only: its G-buffer normal (rgb10a2, the dearest fetch measured) weighed
// creases that depth already separates but for a few pixels along them, and occlusion changes
// smoothly across a crease.
#include "nodes/common/shaders/joint_upsample.glsl"
#include "nodes/occlusion/gtao/shaders/ao_guide.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D ao_guide;
layout(binding = 1) uniform sampler2D bent_low;
layout(binding = 2) uniform sampler2D depth_tex;
layout(binding = 4, r8) uniform writeonly image2D ao;
layout(binding = 5, rgba8_snorm) uniform writeonly image2D bent_normals;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over the grid's
};

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 low_size = textureSize(ao_guide, 0), full_size = imageSize(ao);
  if (any(greaterThanEqual(low, low_size))) return;
  UpsampleGuide guide;
  vec4 occlusion;
  vec4 bent[4];
  for (int t = 0; t < 4; ++t) {
    ivec2 texel = min(low + ivec2(t & 1, t >> 1), low_size - 1);
    AoGuide tap = unpack_ao_guide(texelFetch(ao_guide, texel, 0));
    upsample_guide_tap(guide, t, tap.depth, tap.normal);
    occlusion[t] = tap.occlusion;
    bent[t] = texelFetch(bent_low, texel, 0);
  }
  // The block's first pixel is tap 0's own: its weights are tap 0's alone (bilinear 1, alike to
  // itself), so it takes tap 0 without fetching its depth and normal again. Outside the loop, as
  // lavapipe would run a branch inside it for every pixel.
  ivec2 origin = low * k;
  vec4 own = vec4(0.0);
  if (guide.depth[0] > 0.0) {
    float length_xyz = length(bent[0].xyz);
    own = vec4(length_xyz > 1e-6 ? bent[0].xyz / length_xyz : normalize(guide.normal[0]), bent[0].w);
  }
  imageStore(ao, origin, vec4(guide.depth[0] > 0.0 ? occlusion[0] : 1.0));
  imageStore(bent_normals, origin, own);
  ivec2 end = upsample_block_end(low, k, low_size, full_size);
  int width = end.x - origin.x, count = width * (end.y - origin.y);
  // A do-while, not a for: lavapipe runs a for's body once more, every lane masked off, after
  // its last pass (its exit test comes first and it leaves when no lane is left), a quarter of
  // this loop's work at k = 2.
  int i = 1;
  if (count > 1) do {
    ivec2 texel = origin + ivec2(i % width, i / width);
    float depth = texelFetch(depth_tex, texel, 0).r;
    // The sky, and a surface whose taps are all sky (thinner than k pixels against it), are
    // unoccluded, as horizons.comp writes the sky, with no cone (the open hemisphere to
    // lighting.ibl). Where the taps' cones cancel, their surfaces' normals stand in.
    float visibility = 1.0;
    vec4 cone = vec4(0.0);
    vec4 w = depth > 0.0 ? upsample_weights_facing(guide, depth, vec4(1.0), upsample_fraction(texel, low, k)) : vec4(0.0);
    if (dot(w, vec4(1.0)) > 0.0) {
      visibility = dot(w, occlusion);
      cone = w.x * bent[0] + w.y * bent[1] + w.z * bent[2] + w.w * bent[3];
      vec3 surface = w.x * guide.normal[0] + w.y * guide.normal[1] + w.z * guide.normal[2] + w.w * guide.normal[3];
      float length_xyz = length(cone.xyz), length_surface = length(surface);
      cone.xyz = length_xyz > 1e-6 ? cone.xyz / length_xyz : (length_surface > 1e-6 ? surface / length_surface : vec3(0.0));
    }
    imageStore(ao, texel, vec4(visibility));
    imageStore(bent_normals, texel, cone);
  } while (++i < count);
}
