// lighting.ibl's occlusion formulas (nodes/lighting/ibl/ibl_occlusion.h is the same in double
// precision; docs/env-conventions.md derives them): the visibility cone folded into the SH
// cosine lobe, specular occlusion from the intersection of the visibility cone with a cone
// standing for the specular lobe, and Jimenez et al.'s multi-bounce fit.
#ifndef LG_IBL_OCCLUSION_GLSL
#define LG_IBL_OCCLUSION_GLSL

const float LG_IBL_PI = 3.14159265358979;

// The weights of irradiance SH coefficients 0 to 8 (bands 0 to 2) in the integral of
// L(w) V(w) (n . w) over the visibility cone about b with half-angle cosine c, per unit
// cosine-weighted visibility 1 - c^2: the cone's moments of (n . w), w (n . w) and
// w w^T (n . w) taken against the basis as polynomials, over the cosine lobe's band factors.
// The cone's part below n's horizon counts with its negative cosine.
void cone_lobe_weights(vec3 n, vec3 b, float c, out float w[9]) {
  float bn = dot(b, n);
  vec3 pn = n - bn * b;  // n's part across the axis
  float cosine = LG_IBL_PI * bn;
  float along2 = 2.0 * LG_IBL_PI * (1.0 + c + c * c) / (3.0 * (1.0 + c));
  float across2 = LG_IBL_PI * (1.0 - c) * (2.0 + c) / (3.0 * (1.0 + c));
  float along3 = LG_IBL_PI * (1.0 + c * c) / 2.0, across3 = LG_IBL_PI * (1.0 - c * c) / 4.0;
  vec3 linear = along2 * bn * b + across2 * pn;
  mat3 quadratic = along3 * bn * outerProduct(b, b) +
                   across3 * (outerProduct(b, pn) + outerProduct(pn, b) + bn * (mat3(1.0) - outerProduct(b, b)));
  const float k0 = 0.282094792, k1 = 0.488602512, k2 = 1.092548431, k20 = 0.315391565, k22 = 0.546274215;
  const float a0 = LG_IBL_PI, a1 = 2.0 * LG_IBL_PI / 3.0, a2 = LG_IBL_PI / 4.0;
  w[0] = k0 * cosine / a0;
  w[1] = k1 * linear.y / a1;
  w[2] = k1 * linear.z / a1;
  w[3] = k1 * linear.x / a1;
  w[4] = k2 * quadratic[0][1] / a2;
  w[5] = k2 * quadratic[1][2] / a2;
  w[6] = k20 * (3.0 * quadratic[2][2] - cosine) / a2;
  w[7] = k2 * quadratic[0][2] / a2;
  w[8] = k22 * (quadratic[0][0] - quadratic[1][1]) / a2;
}

// Band 4's zonal factor of the cone-clipped cosine lobe about its axis over the cosine lobe's,
// per unit visibility (used as if n = b).
float cone_band4_ratio(float c) {
  return 1.0 + c * c * (10.0 - 35.0 * c * c);
}

// The cosine of the half-angle of the cone standing for the GGX lobe about the reflection:
// the solid angle of the matching Phong lobe cos^p (p = 2 / alpha^2 - 2) over its peak,
// 2 pi / (p + 1), with alpha = roughness^2. Roughness 1 gives the hemisphere.
float specular_cone_cosine(float roughness) {
  float a2 = roughness * roughness * roughness * roughness;
  return 2.0 * (1.0 - a2) / (2.0 - a2);
}

// The solid angle shared by two spherical caps of half-angle cosines cos1, cos2 (each cap at
// most a hemisphere) whose axes are at cosine cos_d: by Gauss-Bonnet on the lens, exact. The
// lens's angles share one sine numerator sqrt(G), G the Gram determinant of the three
// cosines, and come from atan2: where the caps nearly touch, an error in sqrt(G) then cancels
// to first order between them (three separate acos did not: up to 1% of a narrow lobe in float).
float cap_intersection(float cos1, float cos2, float cos_d) {
  float r1 = acos(clamp(cos1, -1.0, 1.0)), r2 = acos(clamp(cos2, -1.0, 1.0));
  float d = acos(clamp(cos_d, -1.0, 1.0));
  if (d >= r1 + r2) return 0.0;
  if (d <= abs(r1 - r2)) return 2.0 * LG_IBL_PI * (1.0 - max(cos1, cos2));
  float g = sqrt(max(1.0 - cos1 * cos1 - cos2 * cos2 - cos_d * cos_d + 2.0 * cos1 * cos2 * cos_d, 0.0));
  float lens = atan(g, cos_d - cos1 * cos2);
  float edge1 = atan(g, cos2 - cos_d * cos1);
  float edge2 = atan(g, cos1 - cos_d * cos2);
  return max(2.0 * (LG_IBL_PI - lens - cos1 * edge1 - cos2 * edge2), 0.0);
}

// The visible part of the specular lobe's cone (axis r, from roughness) inside the visibility
// cone (axis bent, cosine cone_cos), over its part above the horizon of n: the split sum's DFG
// already leaves out the part below the horizon, so an open plane is unoccluded. The part above
// counts as at least 5% of the lobe, so that a lobe all but below the horizon (r behind the
// surface) does not divide two vanishing areas.
float specular_occlusion_from_cone(vec3 n, vec3 r, vec3 bent, float cone_cos, float roughness) {
  float lobe_cos = specular_cone_cosine(roughness);
  if (1.0 - lobe_cos < 1e-5) return dot(bent, r) >= cone_cos ? 1.0 : 0.0;  // a mirror: one direction
  float above = max(cap_intersection(0.0, lobe_cos, dot(n, r)), 0.05 * 2.0 * LG_IBL_PI * (1.0 - lobe_cos));
  return clamp(cap_intersection(cone_cos, lobe_cos, dot(bent, r)) / above, 0.0, 1.0);
}

// Jimenez et al. 2016's cubic fit of multi-bounce occlusion in the visibility and the albedo,
// per channel, kept within [visibility, 1].
vec3 multi_bounce_occlusion(float visibility, vec3 albedo) {
  vec3 a = 2.0404 * albedo - 0.3324;
  vec3 b = -4.7951 * albedo + 0.6417;
  vec3 c = 2.7552 * albedo + 0.6903;
  float x = visibility;
  return clamp(((a * x + b) * x + c) * x, vec3(x), vec3(1.0));
}

#endif
