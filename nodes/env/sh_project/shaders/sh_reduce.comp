#version 460
// Pass 2 of env.sh_project: adds up the tiles' sums of sh_project.comp, scales each band by
// its factor (window, cosine lobe) and writes (order + 1)^2 coefficients; coefficient 0's w
// gets the number of non-finite texels. One workgroup; each invocation sums a stride of tiles
// with Kahan compensation, then a tree reduction.
layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Partials { vec4 partials[]; };
layout(std430, binding = 1) writeonly buffer Coefficients { vec4 coefficients[]; };
layout(push_constant) uniform Push {
  float band_factor[8];  // per band l: window times (cosine lobe or 1)
  int order;
  int tiles;
};

const int kStride = 25;  // LG_SH_MAX_COUNT sums per tile
shared vec4 lanes[256];

void main() {
  uint lane = gl_LocalInvocationIndex;
  int count = (order + 1) * (order + 1);
  for (int k = 0; k < count; ++k) {
    precise vec4 sum = vec4(0.0), carry = vec4(0.0);
    for (int t = int(lane); t < tiles; t += 256) {
      precise vec4 term = partials[t * kStride + k] - carry;
      precise vec4 next = sum + term;
      carry = (next - sum) - term;
      sum = next;
    }
    lanes[lane] = sum;
    barrier();
    for (uint half_size = 128u; half_size > 0u; half_size /= 2u) {
      if (lane < half_size) lanes[lane] += lanes[lane + half_size];
      barrier();
    }
    if (lane == 0u) {
      int l = int(sqrt(float(k)) + 1e-3);
      coefficients[k] = vec4(lanes[0].xyz * band_factor[l], k == 0 ? lanes[0].w : 0.0);
    }
    barrier();
  }
}
