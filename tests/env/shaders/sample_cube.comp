#version 460
#extension GL_GOOGLE_include_directive : require
// Samples a cube map along given directions with the device's own cube addressing, and also
// evaluates the env nodes' cube_direction / cube_face_uv, for cube_convention_gpu_test.cpp.
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 64) in;

struct Query {
  vec4 direction;  // xyz
  vec4 face_uv;    // x: face, yz: uv for cube_direction
};
struct Answer {
  vec4 sampled;    // the cube's texel along the direction
  vec4 direction;  // cube_direction(face, uv)
  vec4 face_uv;    // cube_face_uv(direction): x face, yz uv
};

layout(binding = 0) uniform samplerCube cube;
layout(std430, binding = 1) readonly buffer Queries { Query queries[]; };
layout(std430, binding = 2) writeonly buffer Answers { Answer answers[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= queries.length()) return;
  Query q = queries[i];
  int face;
  vec2 uv = cube_face_uv(q.direction.xyz, face);
  answers[i].sampled = textureLod(cube, q.direction.xyz, 0.0);
  answers[i].direction = vec4(cube_direction(int(q.face_uv.x), q.face_uv.yz), 0.0);
  answers[i].face_uv = vec4(float(face), uv, 0.0);
}
