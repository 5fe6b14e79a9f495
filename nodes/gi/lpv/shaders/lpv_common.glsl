// What gi.lpv's compute passes share (lpv_kernel.cpp fills the constants, std140): the grid, the
// light, the fixed-point scales of injection, and SH L1 as lpv_model.h defines it.
#ifndef LG_LPV_COMMON_GLSL
#define LG_LPV_COMMON_GLSL

#define LG_PI 3.14159265358979

struct LpvConstants {
  vec4 origin_cell;  // xyz: the grid's corner (nodes/gi/common/cell_grid.h), w: a cell's edge in metres
  ivec4 counts;      // xyz: cells per axis, w: the RSM's edge in texels
  vec4 light;        // xyz: the way the light travels (unit), w: an RSM texel's area across the beam, m^2
  vec4 scales;       // x: fixed-point units per W/sr of injected intensity, y: per unit of occlusion
};

layout(std140, binding = 0) uniform ConstantsBlock { LpvConstants lpv; };

// Coefficients of Y00, Y1-1 (y), Y10 (z), Y11 (x).
vec4 sh_l1_basis(vec3 d) {
  return vec4(0.28209479, 0.48860251 * d.y, 0.48860251 * d.z, 0.48860251 * d.x);
}

// The clamped cosine's SH coefficients: Y00's sqrt(pi) / 2 and Y1m's sqrt(pi / 3) times n.
const float kCosineY00 = 0.88622693, kCosineY1 = 1.02332671;

// max(0, n . w) in SH L1: pi Y00 and 2 pi / 3 Y1m(n).
vec4 sh_l1_cosine_lobe(vec3 n) {
  return vec4(kCosineY00, kCosineY1 * n.y, kCosineY1 * n.z, kCosineY1 * n.x);
}

// The L1 coefficients read as the non-negative distribution with the same projection: an
// isotropic part a plus a clamped-cosine lobe b max(0, d . w) (lpv_model.h's ShLobe).
struct ShLobe {
  float a, b;
  vec3 d;
};

ShLobe sh_l1_lobe(vec4 sh) {
  vec3 band1 = vec3(sh.w, sh.y, sh.z);
  float len = length(band1);
  float c0 = max(sh.x, 0.0);
  float b = min(len / kCosineY1, c0 / kCosineY00);
  return ShLobe(max(c0 - kCosineY00 * b, 0.0) / 3.5449077, b, len > 0.0 ? band1 / len : vec3(0.0));
}

// The lobe packed as (a, b d): its value towards w is a + max(0, (b d) . w).
vec4 sh_l1_lobe_packed(ShLobe l) {
  return vec4(l.a, l.b * l.d);
}

// What a step sends out of a cell from a unit lobe max(0, d . w): its intensity towards each of
// the 30 faces its six neighbours receive through, times their solid angles (lpv_model.h's
// lpv_faces), which falls short of the lobe's power pi by up to 15% (d along an axis) and
// exceeds it by up to 5% (diagonals). lpv_outflow divides that out, so a step keeps the power.
float sh_lobe_sampled_outflow(vec3 d) {
  // Towards the neighbour along e (+-an axis) its far face lies along e, its side faces along
  // (2 e + s) / sqrt(5) for the four s perpendicular to e.
  float sum = 0.0;
  for (int a = 0; a < 3; ++a)
    for (int sign = -1; sign <= 1; sign += 2) {
      float along = float(sign) * d[a];
      float sides = max(2.0 * along + d[(a + 1) % 3], 0.0) + max(2.0 * along - d[(a + 1) % 3], 0.0) +
                    max(2.0 * along + d[(a + 2) % 3], 0.0) + max(2.0 * along - d[(a + 2) % 3], 0.0);
      sum += 0.40066968 * max(along, 0.0) + 0.42343135 / 2.23606798 * sides;
    }
  return sum;
}

// The light a cell sends on, in the form the next step reads: its lobe part scaled by
// pi / sh_lobe_sampled_outflow (so the step keeps its power), as (a, b d): the intensity towards w
// is a + max(0, (b d) . w). Read once per cell here rather than by each of its six neighbours.
vec4 lpv_outflow(vec4 sh) {
  ShLobe l = sh_l1_lobe(sh);
  if (l.b > 0.0) l.b *= LG_PI / sh_lobe_sampled_outflow(l.d);
  return sh_l1_lobe_packed(l);
}

// The lobe's convolution with the clamped cosine about v: the integral over the sphere of
// (a + b max(0, d . w)) max(0, v . w) = pi a + b 2/3 ((pi - t) cos t + sin t), t the angle between
// d and v. With radiance and v = -n: the irradiance on a surface of normal n, whose light travels
// along directions w with w . n < 0 (lpv_model.h's sh_lobe_irradiance).
float sh_l1_lobe_convolve(ShLobe l, vec3 v) {
  float c = clamp(dot(l.d, v), -1.0, 1.0);
  float t = acos(c);
  return LG_PI * l.a + l.b * (2.0 / 3.0) * ((LG_PI - t) * c + sqrt(max(1.0 - c * c, 0.0)));
}

uint lpv_cell_index(ivec3 c) {
  return uint((c.z * lpv.counts.y + c.y) * lpv.counts.x + c.x);
}

bool lpv_inside(ivec3 c) {
  return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, lpv.counts.xyz));
}

// The cell of a one-invocation-per-cell dispatch (width counts.x, height counts.y x counts.z).
ivec3 lpv_invocation_cell() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  return ivec3(id.x, id.y % lpv.counts.y, id.y / lpv.counts.y);
}

// The sky's irradiance on a surface facing m at texture coordinate uvw, from lpv_sky.comp's
// images (the sky's radiance SH times the cells' openness): the filtered radiance over the
// filtered openness, its L1 convolved with the cosine (linear: an open hemisphere gives pi L), at
// least 0.
vec3 lpv_sky_irradiance(sampler3D red, sampler3D green, sampler3D blue, sampler3D openness, vec3 uvw, vec3 m) {
  vec4 cosine = sh_l1_cosine_lobe(-m) / max(textureLod(openness, uvw, 0.0).r, 1e-3);  // arriving along -m
  return max(vec3(dot(textureLod(red, uvw, 0.0), cosine), dot(textureLod(green, uvw, 0.0), cosine),
                  dot(textureLod(blue, uvw, 0.0), cosine)),
             vec3(0.0));
}

#endif
