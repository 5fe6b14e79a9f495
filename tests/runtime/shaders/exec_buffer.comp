// Executor tests: values[i] = (i, value, 0, 1) over a storage buffer of vec4.
#version 460
layout(local_size_x = 64) in;
layout(binding = 0, std430) writeonly buffer Values { vec4 values[]; };
layout(push_constant) uniform Constants { float value; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < values.length()) values[i] = vec4(i, value, 0, 1);
}
