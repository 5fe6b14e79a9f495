// The real SH basis of the env nodes up to band 4 (nodes/env/common/sh_basis.h is the same on
// the CPU): orthonormal, index l (l + 1) + m, polar axis +Z, no Condon-Shortley phase.
#ifndef LG_SH_BASIS_GLSL
#define LG_SH_BASIS_GLSL

const int LG_SH_MAX_COUNT = 25;  // band 4
const float LG_SH_PI = 3.14159265358979;

// Y_lm(d) for every l <= 4 into y[l (l + 1) + m]; `d` is unit. The closed-form polynomials of
// the basis (the recurrence of sh_basis.cpp written out: its square roots and factorials are
// constants, and a shader that evaluated them every call cost env.sh_project most of its time).
void sh_evaluate(vec3 d, out float y[LG_SH_MAX_COUNT]) {
  float x = d.x, yy = d.y, z = d.z;
  float x2 = x * x, y2 = yy * yy, z2 = z * z;
  y[0] = 0.282094791773878;
  y[1] = 0.488602511902920 * yy;
  y[2] = 0.488602511902920 * z;
  y[3] = 0.488602511902920 * x;
  y[4] = 1.092548430592079 * x * yy;
  y[5] = 1.092548430592079 * yy * z;
  y[6] = 0.315391565252520 * (3.0 * z2 - 1.0);
  y[7] = 1.092548430592079 * x * z;
  y[8] = 0.546274215296040 * (x2 - y2);
  y[9] = 0.590043589926644 * yy * (3.0 * x2 - y2);
  y[10] = 2.890611442640554 * x * yy * z;
  y[11] = 0.457045799464466 * yy * (5.0 * z2 - 1.0);
  y[12] = 0.373176332590115 * z * (5.0 * z2 - 3.0);
  y[13] = 0.457045799464466 * x * (5.0 * z2 - 1.0);
  y[14] = 1.445305721320277 * z * (x2 - y2);
  y[15] = 0.590043589926644 * x * (x2 - 3.0 * y2);
  y[16] = 2.503342941796705 * x * yy * (x2 - y2);
  y[17] = 1.770130769779931 * yy * z * (3.0 * x2 - y2);
  y[18] = 0.946174695757560 * x * yy * (7.0 * z2 - 1.0);
  y[19] = 0.669046543557289 * yy * z * (7.0 * z2 - 3.0);
  y[20] = 0.105785546915204 * (35.0 * z2 * z2 - 30.0 * z2 + 3.0);
  y[21] = 0.669046543557289 * x * z * (7.0 * z2 - 3.0);
  y[22] = 0.473087347878780 * (x2 - y2) * (7.0 * z2 - 1.0);
  y[23] = 1.770130769779931 * x * z * (x2 - 3.0 * y2);
  y[24] = 0.625835735449176 * (x2 * (x2 - 3.0 * y2) - y2 * (3.0 * x2 - y2));
}

#endif
