// The real SH basis of the env nodes up to band 4 (nodes/env/common/sh_basis.h is the same on
// the CPU): orthonormal, index l (l + 1) + m, polar axis +Z, no Condon-Shortley phase.
#ifndef LG_SH_BASIS_GLSL
#define LG_SH_BASIS_GLSL

const int LG_SH_MAX_COUNT = 25;  // band 4
const float LG_SH_PI = 3.14159265358979;

// Y_lm(d) for every l <= 4 into y[l (l + 1) + m]; `d` is unit. About 60 loop iterations
// (lavapipe allows an invocation 65535 in all).
void sh_evaluate(vec3 d, out float y[LG_SH_MAX_COUNT]) {
  const int order = 4;
  // P_l^m / sin^m by recurrence, times Re/Im (x + iy)^m: polynomials, no division by sin.
  float re = 1.0, im = 0.0, pmm = 1.0;
  for (int m = 0; m <= order; ++m) {
    float p_prev = 0.0, p = pmm;
    for (int l = m; l <= order; ++l) {
      if (l == m + 1) {
        p_prev = p;
        p = d.z * float(2 * m + 1) * pmm;
      } else if (l > m + 1) {
        float next = (float(2 * l - 1) * d.z * p - float(l + m - 1) * p_prev) / float(l - m);
        p_prev = p;
        p = next;
      }
      float ratio = 1.0;  // (l - m)! / (l + m)!
      for (int k = l - m + 1; k <= l + m; ++k) ratio /= float(k);
      float k_lm = sqrt(float(2 * l + 1) / (4.0 * LG_SH_PI) * ratio);
      if (m == 0) {
        y[l * (l + 1)] = k_lm * p;
      } else {
        y[l * (l + 1) + m] = sqrt(2.0) * k_lm * p * re;
        y[l * (l + 1) - m] = sqrt(2.0) * k_lm * p * im;
      }
    }
    float re_next = re * d.x - im * d.y;
    im = re * d.y + im * d.x;
    re = re_next;
    pmm *= float(2 * m + 1);
  }
}

#endif
