// out[i] = in[i] * 2 + 1 over storage buffers of vec4 (as SH coefficients are stored).
#version 460
layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Source { vec4 source[]; };
layout(binding = 1, std430) writeonly buffer Target { vec4 target[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < source.length()) target[i] = source[i] * 2 + 1;
}
