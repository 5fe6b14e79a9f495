#version 460
#extension GL_GOOGLE_include_directive : require
// A constant environment of radiance 1 seen through the deferred node's BRDF (make_surface,
// share_energy with the albedo table, brdf_cosine: the shader code itself): for each case (n.v, roughness, metalness, albedo), the
// integral of brdf_cosine over every light direction, as if each direction were a distant light
// the deferred pass shades. brdf_cosine's specular part by its visible normals and the rest by
// the cosine, each over a Hammersley set, so any roughness resolves; the GGX density is taken
// at the half vector specular_term itself computes, so it cancels even at alpha 1e-3.
#include "nodes/common/shaders/brdf.glsl"
#include "nodes/env/common/shaders/ggx_sampling.glsl"

layout(std140, binding = 2) uniform Table { vec4 brdf_albedo[512]; };  // as lights.glsl's constants
#include "nodes/env/brdf_lut/shaders/brdf_albedo.glsl"

layout(local_size_x = 64) in;

struct Case {
  vec4 view_material;  // n.v, roughness, metalness, albedo
};

layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec2 reflected[]; };  // specular, diffuse
const uint samples = 4096u;  // within lavapipe's loop budget (docs/env-conventions.md)

float smith_g1(float n_dot_v, float alpha) {
  float a2 = alpha * alpha;
  return 2.0 * n_dot_v / (n_dot_v + sqrt(a2 + (1.0 - a2) * n_dot_v * n_dot_v));
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  vec4 c = cases[i].view_material;
  float n_dot_v = c.x;
  vec3 v = vec3(sqrt(max(1.0 - n_dot_v * n_dot_v, 0.0)), 0.0, n_dot_v);
  Surface s = make_surface(vec3(0.0), vec3(0.0, 0.0, 1.0), v, vec3(c.w), c.y, c.z);
  share_energy(s, brdf_albedo_lookup(max(n_dot_v, 1e-4), c.y));  // as surface.glsl does
  float specular = 0.0, diffuse = 0.0;
  for (uint k = 0u; k < samples; ++k) {
    vec2 xi = hammersley(k, samples);
    vec3 m = sample_ggx_visible_normal(s.view, xi, s.alpha);
    vec3 l = reflect(-s.view, m);
    if (l.z > 0.0) {
      vec3 h = normalize(l + s.view);  // as specular_term takes it
      float pdf = smith_g1(max(s.view.z, 1e-4), s.alpha) * ggx_distribution(clamp(h.z, 0.0, 1.0), s.alpha) /
                  (4.0 * max(s.view.z, 1e-4));
      specular += specular_term(s, l, s.alpha).g / pdf;
    }
    float r = sqrt(xi.x), phi = 6.28318530717959 * xi.y;
    vec3 d = vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - xi.x, 0.0)));
    if (d.z > 0.0) diffuse += (brdf_cosine(s, d) - specular_term(s, d, s.alpha)).g / (d.z / LG_BRDF_PI);
  }
  reflected[i] = vec2(specular, diffuse) / float(samples);
}
