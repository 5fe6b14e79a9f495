// Importance sampling of the GGX distribution (alpha = roughness^2) for the env nodes: a
// Hammersley point set, and half vectors about +Z by the distribution or by its visible normals.
#ifndef LG_GGX_SAMPLING_GLSL
#define LG_GGX_SAMPLING_GLSL

// Point i of an n-point Hammersley set in [0, 1)^2.
vec2 hammersley(uint i, uint n) {
  return vec2((float(i) + 0.5) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

// A half vector about +Z with density D(h) (n.h) for xi in [0, 1)^2; alpha 0 gives +Z.
vec3 sample_ggx_half_vector(vec2 xi, float alpha) {
  float a2 = alpha * alpha;
  float cos2 = (1.0 - xi.x) / max(1.0 + (a2 - 1.0) * xi.x, 1e-30);
  float cos_theta = sqrt(clamp(cos2, 0.0, 1.0));
  float sin_theta = sqrt(clamp(1.0 - cos2, 0.0, 1.0));
  float phi = 6.28318530717959 * xi.y;
  return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

// A half vector about +Z drawn from the GGX distribution of normals visible from `v` (unit,
// v.z > 0), density G1(v) max(v.h, 0) D(h) / v.z (Heitz 2018); alpha 0 gives +Z. Far lower
// variance than D (n.h) at grazing views.
vec3 sample_ggx_visible_normal(vec3 v, vec2 xi, float alpha) {
  vec3 vh = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
  float len2 = dot(vh.xy, vh.xy);
  vec3 t1 = len2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(xi.x), phi = 6.28318530717959 * xi.y;
  float p1 = r * cos(phi);
  float s = 0.5 * (1.0 + vh.z);
  float p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * r * sin(phi);
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(nh.z, 1e-7)));
}

#endif
