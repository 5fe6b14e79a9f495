// The microfacet BRDF every lighting node shares: GGX distribution, height-correlated Smith
// visibility, Schlick Fresnel, Lambert diffuse; alpha = roughness^2 (perceptual roughness). The
// specular carries the multiple-scattering compensation and the diffuse gets what the specular
// leaves at the view (share_energy, brdf_energy.glsl), so the lobes integrate to 1 for a white
// surface.
#ifndef LG_BRDF_GLSL
#define LG_BRDF_GLSL

#include "nodes/common/shaders/brdf_energy.glsl"

const float LG_BRDF_PI = 3.14159265358979;
const float LG_MIN_ALPHA = 1e-3;  // a mirror's highlight from a point light stays finite

float ggx_distribution(float n_dot_h, float alpha) {
  float a2 = alpha * alpha;
  float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  return a2 / (LG_BRDF_PI * d * d);
}

// G2 / (4 n.l n.v), height-correlated (Heitz 2014).
float smith_visibility(float n_dot_v, float n_dot_l, float alpha) {
  float a2 = alpha * alpha;
  float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
  float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
  return 0.5 / max(gv + gl, 1e-7);
}

vec3 fresnel_schlick(vec3 f0, float v_dot_h) {
  float f = pow(1.0 - clamp(v_dot_h, 0.0, 1.0), 5.0);
  return f0 + (1.0 - f0) * f;
}

struct Surface {
  vec3 position;
  vec3 normal;
  vec3 view;  // unit, toward the eye
  vec3 diffuse_color;   // albedo (1 - metalness), times 1 - the specular albedo after share_energy
  vec3 f0;              // specular reflectance at normal incidence
  vec3 specular_scale;  // multiple-scattering compensation at the view
  vec3 specular_albedo;  // the specular lobe's directional albedo at the view, with that scale
  float lobe_albedo;     // A + B: that albedo with Fresnel 1 and no scale
  float alpha;
};

Surface make_surface(vec3 position, vec3 normal, vec3 eye, vec3 albedo, float roughness, float metalness) {
  Surface s;
  s.position = position;
  s.normal = normal;
  s.view = normalize(eye - position);
  s.f0 = mix(vec3(0.04), albedo, metalness);
  s.specular_scale = vec3(1.0);
  s.specular_albedo = s.f0;  // until share_energy has the table's value
  s.lobe_albedo = 1.0;
  s.diffuse_color = albedo * (1.0 - metalness);
  s.alpha = max(roughness * roughness, LG_MIN_ALPHA);
  return s;
}

// The lobes' energy sharing at the surface's view from the GGX lobe's (A, B) there (brdf_albedo.glsl's
// brdf_albedo_lookup(max(n.v, 1e-4), roughness) for direct light): the specular's multiple-
// scattering scale, and the diffuse reduced to what the specular leaves.
void share_energy(inout Surface s, vec2 scale_bias) {
  s.specular_scale = specular_energy_scale(s.f0, scale_bias);
  s.specular_albedo = specular_albedo(s.f0, scale_bias);
  s.lobe_albedo = white_albedo(scale_bias);
  s.diffuse_color *= 1.0 - s.specular_albedo;
}

// Specular BRDF times n.l for light arriving from unit direction l.
vec3 specular_term(Surface s, vec3 l, float alpha) {
  float n_dot_l = dot(s.normal, l);
  float n_dot_v = max(dot(s.normal, s.view), 1e-4);
  if (n_dot_l <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + s.view);
  float n_dot_h = clamp(dot(s.normal, h), 0.0, 1.0);
  return ggx_distribution(n_dot_h, alpha) * smith_visibility(n_dot_v, n_dot_l, alpha) *
         fresnel_schlick(s.f0, dot(s.view, h)) * s.specular_scale * n_dot_l;
}

// (diffuse + specular BRDF) times n.l.
vec3 brdf_cosine(Surface s, vec3 l) {
  float n_dot_l = max(dot(s.normal, l), 0.0);
  return s.diffuse_color / LG_BRDF_PI * n_dot_l + specular_term(s, l, s.alpha);
}

#endif
