#version 460
// Pass 2 of env.sh_project: adds up the blocks' sums of sh_project.comp, scales each band by its
// factor (window, cosine lobe) and writes (order + 1)^2 coefficients; coefficient 0's w gets the
// number of non-finite texels. One workgroup, an invocation per coefficient summing every block
// with Kahan compensation: no barrier (each costs a pass over the workgroup on lavapipe), and at
// most 6 x 512 blocks (1024^2 faces) stay inside lavapipe's loop budget.
layout(local_size_x = 32) in;

layout(std430, binding = 0) readonly buffer Partials { vec4 partials[]; };
layout(std430, binding = 1) writeonly buffer Coefficients { vec4 coefficients[]; };
layout(push_constant) uniform Push {
  float band_factor[8];  // per band l: window times (cosine lobe or 1)
  int order;
  int blocks;
};

const int kStride = 25;  // LG_SH_MAX_COUNT sums per block

void main() {
  const int k = int(gl_LocalInvocationIndex);
  if (k >= (order + 1) * (order + 1)) return;
  precise vec4 sum = vec4(0.0), carry = vec4(0.0);
  for (int b = 0; b < blocks; ++b) {
    precise vec4 term = partials[b * kStride + k] - carry;
    precise vec4 next = sum + term;
    carry = (next - sum) - term;
    sum = next;
  }
  const int l = int(sqrt(float(k)) + 1e-3);
  coefficients[k] = vec4(sum.xyz * band_factor[l], k == 0 ? sum.w : 0.0);
}
