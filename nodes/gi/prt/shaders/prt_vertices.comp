#version 460
// gi.prt, the dispatch before its drawing: every baked vertex's irradiance E = sum_k T_k L'_k,
// with L' the environment's radiance SH turned by this frame's rotation (sh_rotation.h's band
// matrices), and its validity. Vertices lie on rows of 256 invocations; each workgroup first
// turns the coefficients into shared memory.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer Sh { vec4 sh[]; };            // env.sh_project's, radiance
layout(std430, binding = 1) readonly buffer Rotation { float rotation[]; };  // band l at l(2l-1)(2l+1)/3
layout(std430, binding = 2) readonly buffer Transfer { float transfer[]; };  // stride floats a vertex
layout(std430, binding = 3) writeonly buffer VertexIrradiance { vec4 vertex_irradiance[]; };
layout(push_constant) uniform Push {
  uint vertices;
  uint stride;          // 3 floats per coefficient of the bake's order, then the validity
  uint order;           // of the coefficients used: the lowest of the bake's, the node's and the SH's
  uint clamp_negative;  // 1: E at least 0 (SH ringing must not light negatively)
};

const uint kRowWidth = 256u;
shared vec3 turned[25];

void main() {
  uint lane = gl_LocalInvocationIndex;
  uint count = (order + 1u) * (order + 1u);
  if (lane < count) {
    uint l = uint(sqrt(float(lane) + 0.5));
    uint n = 2u * l + 1u, row = lane - l * l, block = l * (2u * l - 1u) * (2u * l + 1u) / 3u;
    vec3 sum = vec3(0.0);
    for (uint c = 0u; c < n; ++c) sum += rotation[block + row * n + c] * sh[l * l + c].rgb;
    turned[lane] = sum;
  }
  barrier();
  uint v = gl_GlobalInvocationID.y * kRowWidth + gl_GlobalInvocationID.x;
  if (gl_GlobalInvocationID.x >= kRowWidth || v >= vertices) return;
  uint base = v * stride;
  vec3 e = vec3(0.0);
  for (uint k = 0u; k < count; ++k)
    e += vec3(transfer[base + 3u * k], transfer[base + 3u * k + 1u], transfer[base + 3u * k + 2u]) * turned[k];
  if (clamp_negative != 0u) e = max(e, vec3(0.0));
  vertex_irradiance[v] = vec4(e, transfer[base + stride - 1u]);
}
