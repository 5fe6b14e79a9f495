#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's propagation step, one invocation per cell (gathering): the light of each face
// neighbour that travels into this cell through the five faces of it that do not face back (the
// neighbour's coefficients read as a lobe, sh_l1_lobe), re-emitted from its centre as cosine lobes
// about the directions it crossed those faces in; added to the sum, and sent on by the next step
// with its lobe part scaled to keep its power (lpv_outflow). The model and its face table are
// lpv_model.h's (the kernel uploads the table).
#include "nodes/gi/lpv/shaders/lpv_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer LightIn { vec4 light_in[]; };  // 3 a cell
layout(std430, binding = 2) writeonly buffer LightOut { vec4 light_out[]; };
layout(std430, binding = 3) buffer Sum { vec4 sum[]; };
layout(std430, binding = 4) readonly buffer Occlusion { vec4 occlusion[]; };
// Per direction d (lpv_directions()) and face f, at 5 d + f: the SH basis towards the face and
// the lobe its flux is re-emitted with.
layout(std140, binding = 5) uniform Faces {
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
  uint i = lpv_cell_index(c);
  vec4 here = occlusion[i];
  vec4 gathered[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  for (int d = 0; d < 6; ++d) {
    ivec3 s = c - directions[d];
    if (!lpv_inside(s)) continue;
    uint j = lpv_cell_index(s);
    ShLobe source[3] = ShLobe[3](sh_l1_lobe(light_in[3u * j]), sh_l1_lobe(light_in[3u * j + 1u]),
                                 sh_l1_lobe(light_in[3u * j + 2u]));
    // The occlusion between the two cells, read opposite the way the light goes: the basis at
    // -w is the basis at w with band 1 negated.
    vec4 between = 0.5 * (occlusion[j] + here) * vec4(1.0, -1.0, -1.0, -1.0);
    for (int f = 0; f < 5; ++f) {
      vec4 y = face_basis[5 * d + f];
      vec3 towards = vec3(y.w, y.y, y.z) / 0.48860251;
      float pass = occlude != 0u ? 1.0 - clamp(dot(between, y), 0.0, 1.0) : 1.0;
      vec4 lobe = face_lobe[5 * d + f] * pass;
      for (int ch = 0; ch < 3; ++ch) gathered[ch] += sh_l1_lobe_eval(source[ch], towards) * lobe;
    }
  }
  for (uint ch = 0u; ch < 3u; ++ch) {
    light_out[3u * i + ch] = lpv_outflow(gathered[ch]);
    sum[3u * i + ch] += gathered[ch];
  }
}
