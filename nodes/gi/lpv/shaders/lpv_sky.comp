#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's sky, one invocation per cell, with the environment's SH linked: the sky's light that
// reaches the cell through the geometry volume, added to the sum the lookup reads (not
// propagated: the march below already carries it the whole way). kSkyDirections fixed directions
// (a spherical Fibonacci set, equal solid angles) are marched from the cell's centre cell by cell
// to the grid's edge; past it lies the sky. Each cell crossed lets 1 - its blocking through, the
// blocking counted whichever way its surfaces face (a + b of the occlusion lobe, clamped to 1):
// an opaque surface hides the sky from both sides, and the inside faces of a closed room, turned
// away from a sky outside, must still block it. The cell's own surfaces block only the light
// arriving from behind them (a + max(0, -b d . w)): a floor's cell sees the sky above it, not
// below. Every direction's sky radiance (the cosine-convolved SH deconvolved, bands 0-2) times
// its transmittance is projected to SH L1 in the direction the light travels (-w), as radiant
// intensity over the cell (radiance x cell^2, the sum's unit, lpv_store.comp).
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/env/common/shaders/sh_basis.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler3D occlusion;  // lpv_resolve.comp's lobes (a, b d)
// The environment's irradiance SH (env.sh_project with convolve_cosine), rgb per coefficient.
layout(std430, binding = 2) readonly buffer Sh { vec4 sh[]; };
layout(std430, binding = 3) buffer Sum { vec4 sum[]; };  // 3 a cell

// 32 directions: 4 pi / 32 sr each. Measured against 64 (docs/lpv.md).
const int kSkyDirections = 32;
const float kGoldenAngle = 2.39996323;
const float kStopBelow = 1e-3;  // transmittance below which a direction's sky is dark

vec3 sky_direction(int k) {
  float z = 1.0 - (2.0 * float(k) + 1.0) / float(kSkyDirections);
  float r = sqrt(max(1.0 - z * z, 0.0));
  float phi = kGoldenAngle * float(k);
  return vec3(r * cos(phi), r * sin(phi), z);
}

// The sky's radiance from direction w: the irradiance SH over the clamped cosine's bands
// (pi, 2 pi / 3, pi / 4), bands above 2 left out (the cosine's band 3 is 0, band 4 tiny).
vec3 sky_radiance(vec3 w, int count) {
  float y[LG_SH_MAX_COUNT];
  sh_evaluate(w, y);
  const float inverse_band[3] = float[3](1.0 / LG_PI, 1.5 / LG_PI, 4.0 / LG_PI);
  vec3 l = vec3(0.0);
  for (int k = 0; k < count; ++k) l += finite_or_zero(sh[k].rgb) * (y[k] * inverse_band[k < 1 ? 0 : (k < 4 ? 1 : 2)]);
  return max(l, vec3(0.0));  // ringing must not light negatively
}

float blocking(ivec3 cell) {
  vec4 o = texelFetch(occlusion, cell, 0);
  return clamp(o.x + length(o.yzw), 0.0, 1.0);
}

// The share of the sky along w that reaches cell c's centre: a walk through the cells the ray
// crosses (each once), from c to the grid's edge.
float transmittance(ivec3 c, vec3 w) {
  vec4 own = texelFetch(occlusion, c, 0);
  float t = 1.0 - clamp(own.x + max(0.0, -dot(own.yzw, w)), 0.0, 1.0);
  ivec3 cell = c;
  ivec3 step = ivec3(sign(w));
  vec3 delta = 1.0 / max(abs(w), vec3(1e-6));  // along w, per cell crossed on each axis
  vec3 next = 0.5 * delta;                      // to the first face on each axis, from the centre
  do {
    int axis = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
    cell[axis] += step[axis];
    next[axis] += delta[axis];
    if (!lpv_inside(cell)) break;
    t *= 1.0 - blocking(cell);
  } while (t > kStopBelow);
  return t;
}

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  int count = min(int(sh.length()), 9);
  vec4 red = vec4(0.0), green = vec4(0.0), blue = vec4(0.0);
  int k = 0;
  do {
    vec3 w = sky_direction(k);
    float t = transmittance(c, w);
    if (t > kStopBelow) {
      vec3 l = sky_radiance(w, count) * t;
      vec4 travelling = sh_l1_basis(-w);
      red += l.r * travelling, green += l.g * travelling, blue += l.b * travelling;
    }
  } while (++k < kSkyDirections);
  float weight = 4.0 * LG_PI / float(kSkyDirections) * lpv.origin_cell.w * lpv.origin_cell.w;
  uint i = 3u * lpv_cell_index(c);
  sum[i] += finite_or_zero(red * weight);
  sum[i + 1u] += finite_or_zero(green * weight);
  sum[i + 2u] += finite_or_zero(blue * weight);
}
