// lighting.ibl's occlusion formulas (nodes/lighting/ibl/ibl_occlusion.h is the same in double
// precision; nodes/lighting/ibl/README.md derives them): the visibility cone folded into the SH
// cosine lobe, specular occlusion from the intersection of the visibility cone with a cone
// standing for the specular lobe, and Jimenez et al.'s multi-bounce fit.
#ifndef LG_IBL_OCCLUSION_GLSL
#define LG_IBL_OCCLUSION_GLSL

const float LG_IBL_PI = 3.14159265358979;

// Band l's factor of the cosine lobe clipped to a cone about its own axis (cosine c of the
// half-angle), over the plain cosine lobe's band factor, per unit cosine-weighted visibility
// 1 - c^2. Band 3: irradiance coefficients carry none (the cosine lobe has none), so 0.
void cone_lobe_band_ratios(float c, out float ratio[5]) {
  float c2 = c * c;
  ratio[0] = 1.0;
  ratio[1] = (1.0 + c + c2) / (1.0 + c);
  ratio[2] = 1.0 + 3.0 * c2;
  ratio[3] = 0.0;
  ratio[4] = 1.0 + c2 * (10.0 - 35.0 * c2);
}

// The cosine of the half-angle of the cone standing for the GGX lobe about the reflection:
// the solid angle of the matching Phong lobe cos^p (p = 2 / alpha^2 - 2) over its peak,
// 2 pi / (p + 1), with alpha = roughness^2. Roughness 1 gives the hemisphere.
float specular_cone_cosine(float roughness) {
  float a2 = roughness * roughness * roughness * roughness;
  return 2.0 * (1.0 - a2) / (2.0 - a2);
}

// The solid angle shared by two spherical caps of half-angle cosines cos1, cos2 (each cap at
// most a hemisphere) whose axes are at cosine cos_d: by Gauss-Bonnet on the lens, exact.
float cap_intersection(float cos1, float cos2, float cos_d) {
  float r1 = acos(clamp(cos1, -1.0, 1.0)), r2 = acos(clamp(cos2, -1.0, 1.0));
  float d = acos(clamp(cos_d, -1.0, 1.0));
  if (d >= r1 + r2) return 0.0;
  if (d <= abs(r1 - r2)) return 2.0 * LG_IBL_PI * (1.0 - max(cos1, cos2));
  float s1 = sqrt(max(1.0 - cos1 * cos1, 1e-12)), s2 = sqrt(max(1.0 - cos2 * cos2, 1e-12));
  float sd = sqrt(max(1.0 - cos_d * cos_d, 1e-12));
  float lens = acos(clamp((cos_d - cos1 * cos2) / (s1 * s2), -1.0, 1.0));
  float edge1 = acos(clamp((cos2 - cos_d * cos1) / (sd * s1), -1.0, 1.0));
  float edge2 = acos(clamp((cos1 - cos_d * cos2) / (sd * s2), -1.0, 1.0));
  return max(2.0 * (LG_IBL_PI - lens - cos1 * edge1 - cos2 * edge2), 0.0);
}

// The visible part of the specular lobe's cone (axis r, from roughness) inside the visibility
// cone (axis bent, cosine cone_cos), over its part above the horizon of n: the split sum's DFG
// already leaves out the part below the horizon, so an open plane is unoccluded.
float specular_occlusion_from_cone(vec3 n, vec3 r, vec3 bent, float cone_cos, float roughness) {
  float lobe_cos = specular_cone_cosine(roughness);
  if (1.0 - lobe_cos < 1e-5) return dot(bent, r) >= cone_cos ? 1.0 : 0.0;  // a mirror: one direction
  float above = cap_intersection(0.0, lobe_cos, dot(n, r));
  if (above <= 0.0) return 1.0;
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
