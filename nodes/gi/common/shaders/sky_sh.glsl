// The environment's light from its cosine-convolved SH (env.sh_project with convolve_cosine, one
// vec4 a coefficient), for the GI nodes that take the sky: gi.voxel's injection (a voxel's
// irradiance) and cones (the sky's radiance where a cone leaves the grid), gi.lpv's march of the
// sky through its grid. Non-finite coefficients read as 0. Define LG_SKY_SH_BINDING before
// including.
#ifndef LG_SKY_SH_GLSL
#define LG_SKY_SH_GLSL

#include "nodes/common/shaders/finite.glsl"
#include "nodes/env/common/shaders/sh_basis.glsl"

layout(std430, binding = LG_SKY_SH_BINDING) readonly buffer Sh { vec4 sh[]; };

// The sky's irradiance at unit normal n, W/m^2 (lighting.ibl's sh_irradiance, whose bindings
// these passes do not have).
vec3 sky_irradiance(vec3 n) {
  float y[LG_SH_MAX_COUNT];
  sh_evaluate(n, y);
  vec3 e = vec3(0.0);
  for (int k = 0; k < min(int(sh.length()), LG_SH_MAX_COUNT); ++k) e += finite_or_zero(sh[k].rgb) * y[k];
  return max(e, vec3(0.0));  // ringing must not light negatively
}

// The number of the SH's coefficients sky_radiance() reads: bands 0-2 (the cosine kernel's band
// 3 is 0 and band 4 is 1/24 of band 0's, so deconvolving them would only amplify the projection's
// ringing).
const int kSkyRadianceCoefficients = 9;

// The sky's radiance along unit direction d, W/m^2/sr, from the SH `e` (as
// sky_radiance_coefficients() reads them): the irradiance deconvolved by the cosine
// kernel's band factors A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 (Ramamoorthi and Hanrahan 2001).
// Exact for a sky of bands 0-2: with E(d) / pi gi.voxel's six cones gathered 62.5% of a linear
// sky's gradient, with this 94% (voxel_trace.glsl's weights: sum w_i d_i = 0.625 n).
vec3 sky_radiance(vec3 e[kSkyRadianceCoefficients], vec3 d) {
  float y[LG_SH_MAX_COUNT];
  sh_evaluate(d, y);
  vec3 band1 = e[1] * y[1] + e[2] * y[2] + e[3] * y[3];
  vec3 band2 = e[4] * y[4] + e[5] * y[5] + e[6] * y[6] + e[7] * y[7] + e[8] * y[8];
  return max((e[0] * y[0] + 1.5 * band1 + 4.0 * band2) / LG_PI, vec3(0.0));
}

// The SH's first kSkyRadianceCoefficients coefficients (0 past its length), read once an
// invocation: lavapipe loads a storage buffer one lane at a time (docs/lavapipe-costs.md).
void sky_radiance_coefficients(out vec3 e[kSkyRadianceCoefficients]) {
  int count = min(int(sh.length()), kSkyRadianceCoefficients);
  for (int k = 0; k < kSkyRadianceCoefficients; ++k) e[k] = k < count ? finite_or_zero(sh[k].rgb) : vec3(0.0);
}

#endif
