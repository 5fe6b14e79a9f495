#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's propagation step, one invocation per cell (gathering): the light of each face
// neighbour that travels into this cell through the five faces of it that do not face back (the
// neighbour's light as lpv_outflow left it, a lobe a + max(0, (b d) . w)), re-emitted from its
// centre as cosine lobes about the directions it crossed those faces in; added to the sum, and
// sent on by the next step (lpv_outflow). The model and its face table are lpv_model.h's (the
// kernel uploads the table). The neighbours' light and occlusion are read from 3D images with
// texelFetch: lavapipe gathers those, where it read a storage buffer's vec4 lane by lane, which
// made a step cost several times as much.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler3D in_red;  // lpv_outflow's form
layout(binding = 2) uniform sampler3D in_green;
layout(binding = 3) uniform sampler3D in_blue;
layout(binding = 4, rgba32f) uniform writeonly image3D out_red;
layout(binding = 5, rgba32f) uniform writeonly image3D out_green;
layout(binding = 6, rgba32f) uniform writeonly image3D out_blue;
layout(std430, binding = 7) buffer Sum { vec4 sum[]; };  // SH L1, 3 a cell
layout(binding = 8) uniform sampler3D occlusion;
// Per direction d (lpv_directions()) and face f, at 5 d + f: the SH basis towards the face and
// the lobe its flux is re-emitted with.
layout(std140, binding = 9) uniform Faces {
  vec4 face_basis[30];
  vec4 face_lobe[30];
};
layout(push_constant) uniform Push {
  uint occlude;  // 1: the geometry volume blocks (never at the first step)
};

const ivec3 directions[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1),
                                     ivec3(0, 0, -1));

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  vec4 here = texelFetch(occlusion, c, 0);
  vec4 red = vec4(0.0), green = vec4(0.0), blue = vec4(0.0);
  for (int d = 0; d < 6; ++d) {
    ivec3 s = c - directions[d];
    if (!lpv_inside(s)) continue;
    vec4 r = texelFetch(in_red, s, 0), g = texelFetch(in_green, s, 0), b = texelFetch(in_blue, s, 0);
    vec4 there = texelFetch(occlusion, s, 0);
    for (int f = 0; f < 5; ++f) {
      vec4 y = face_basis[5 * d + f];
      vec3 towards = vec3(y.w, y.y, y.z) / 0.48860251;
      // The mean of the two cells' occlusion lobes (lpv_resolve.comp) opposite the way the light
      // goes: a surface blocks light that travels into it, not light that runs along it.
      float block = 0.5 * (here.x + there.x + max(dot(here.yzw, -towards), 0.0) + max(dot(there.yzw, -towards), 0.0));
      float pass = occlude != 0u ? 1.0 - clamp(block, 0.0, 1.0) : 1.0;
      vec4 lobe = face_lobe[5 * d + f] * pass;
      red += (r.x + max(dot(r.yzw, towards), 0.0)) * lobe;
      green += (g.x + max(dot(g.yzw, towards), 0.0)) * lobe;
      blue += (b.x + max(dot(b.yzw, towards), 0.0)) * lobe;
    }
  }
  imageStore(out_red, c, lpv_outflow(red));
  imageStore(out_green, c, lpv_outflow(green));
  imageStore(out_blue, c, lpv_outflow(blue));
  uint i = lpv_cell_index(c);
  sum[3u * i] += red;
  sum[3u * i + 1u] += green;
  sum[3u * i + 2u] += blue;
}
