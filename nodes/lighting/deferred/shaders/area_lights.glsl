// Sphere, tube and rectangle lights on a surface: exact diffuse irradiance
// (area_light_formulas.glsl) and GGX specular by linearly transformed cosines
// (area_light_ltc.glsl) or by representative points with energy normalisation
// (area_light_specular.glsl), both times the light's visibility from its shadow map
// (area_shadows.glsl). lighting.deferred's area pass and scene.forward_transparent's surfaces;
// bindings 16 to 18, the LTC table at 22, the atlas at 14 and 15, the constants at 0 (lights.glsl).
#ifndef LG_AREA_LIGHTS_GLSL
#define LG_AREA_LIGHTS_GLSL

#include "nodes/common/shaders/brdf.glsl"
#include "nodes/lighting/deferred/shaders/area_light_formulas.glsl"
#include "nodes/lighting/deferred/shaders/area_light_ltc.glsl"
#include "nodes/lighting/deferred/shaders/area_light_specular.glsl"
#include "nodes/lighting/deferred/shaders/area_shadows.glsl"
#include "nodes/lighting/deferred/shaders/lights.glsl"

layout(std140, binding = 16) uniform Spheres { SphereLight spheres[LG_MAX_LIGHTS]; };
layout(std140, binding = 17) uniform Tubes { TubeLight tubes[LG_MAX_LIGHTS]; };
layout(std140, binding = 18) uniform Rects { RectLight rects[LG_MAX_LIGHTS]; };
#define LG_LTC_BINDING 22
#include "nodes/lighting/deferred/shaders/ltc_table.glsl"

// lighting.deferred's area_specular: true for "ltc", false for "representative_point" (the
// compiler drops the other); scene.forward_transparent keeps the default.
layout(constant_id = 1) const bool area_specular_ltc = true;
// lighting.deferred's area pass: whether the frame has lights of each kind, so that the compiler
// drops an absent kind's loop. lavapipe (Mesa 22.3) runs a branch's body with the lanes that did
// not take it masked off, whatever the lanes decide, so the `if` around an empty list's loop
// still cost a whole light. scene.forward_transparent keeps the defaults (its lists are tested
// at run time).
layout(constant_id = 5) const bool area_has_spheres = true;
layout(constant_id = 6) const bool area_has_tubes = true;
layout(constant_id = 7) const bool area_has_rects = true;

// True where every point of the light's bounding sphere (centre c, radius `bound`) lies below the
// surface's horizon: neither its diffuse nor its specular (the GGX lobe is clipped there) can
// reach the point, so the light is skipped (exact; whole tiles of a wall or of a sphere's far
// side skip its cost).
bool below_horizon(Surface s, vec3 c, float bound) {
  return dot(s.normal, c - s.position) < -bound;
}

vec3 reflection_dir(Surface s) {
  return reflect(-s.view, s.normal);
}

// The representative point shaded as a point light whose intensity is the light's radiance
// times its projected area toward the point (`area`, m^2), at most what the whole lobe reflects
// of that radiance (its directional albedo, as the LTC path's I <= 1): a light that covers a
// narrow lobe's peak read its peak over all its solid angle, up to 5x the lobe's albedo on the
// benchmark's points (docs/bench/area-specular) and 15x under a wide light
// (AreaSpecular.NoLightReflectsMoreThanTheWholeLobe).
vec3 area_specular(Surface s, RepresentativePoint rp, vec3 radiance, float area) {
  if (rp.normalization <= 0.0) return vec3(0.0);
  float d2 = max(rp.distance * rp.distance, 1e-8);
  return min(specular_term(s, rp.direction, s.alpha) * radiance * (area / d2 * rp.normalization),
             radiance * s.specular_albedo);
}

// Radiance toward the eye from every sphere, tube and rectangle light. The loops are do-whiles:
// lavapipe leaves a loop only when no lane is left in it, so a `for`, whose exit test comes
// first, runs its body once more after the last light with every lane masked off (one light
// cost two); a do-while runs n bodies for n lights. A `continue` there goes to the test.
vec3 area_radiance(Surface s) {
  vec3 diffuse_brdf = s.diffuse_color / LG_PI;
  vec3 r = reflection_dir(s);
  // alpha = roughness^2 above its floor, where the table's entries are alike.
  float n_dot_v = max(dot(s.normal, s.view), 1e-4);
  LtcLobe ltc = ltc_lobe(ltc_lookup(n_dot_v, sqrt(s.alpha)), n_dot_v, s.alpha, s.lobe_albedo);
  vec3 added = vec3(0.0);
  if (area_has_spheres && counts.z > 0u) {
    uint i = 0u;
    do {
      SphereLight l = spheres[i];
      vec3 c = l.center_radius.xyz;
      float radius = l.center_radius.w;
      if (below_horizon(s, c, radius)) continue;
      vec3 radiance = l.radiance.rgb * area_visibility(s, l.radiance.w, c, sphere_extent(radius, normalize(s.position - c)));
      added += diffuse_brdf * radiance * sphere_irradiance(c, radius, s.position, s.normal);
      if (area_specular_ltc) {
        added += radiance * s.specular_albedo * ltc_sphere_specular(c, radius, s.position, s.normal, s.view, ltc);
        continue;
      }
      RepresentativePoint rp = sphere_specular_point(c, radius, s.position, r, s.alpha);
      added += area_specular(s, rp, radiance, LG_PI * radius * radius);
    } while (++i < counts.z);
  }
  if (area_has_tubes && counts.w > 0u) {
    uint i = 0u;
    do {
      TubeLight l = tubes[i];
      vec3 a = l.end0_radius.xyz, b = l.end1.xyz;
      float radius = l.end0_radius.w;
      vec3 c = 0.5 * (a + b);
      if (below_horizon(s, c, 0.5 * length(b - a) + radius)) continue;
      vec3 radiance = l.radiance.rgb * area_visibility(s, l.end1.w, c, tube_extent(a, b, radius, normalize(s.position - c)));
      added += diffuse_brdf * radiance * tube_irradiance(a, b, radius, s.position, s.normal);
      if (area_specular_ltc) {
        added += radiance * s.specular_albedo * ltc_tube_specular(a, b, radius, s.position, s.normal, s.view, ltc);
        continue;
      }
      RepresentativePoint rp = tube_specular_point(a, b, radius, s.position, r, s.alpha);
      // Seen from the side a capsule shows its caps' disc and the cylinder's length x diameter.
      vec3 axis = b - a;
      float len = length(axis);
      float sin_side = len > 0.0 ? length(cross(axis / len, rp.direction)) : 0.0;
      added += area_specular(s, rp, radiance, LG_PI * radius * radius + 2.0 * radius * len * sin_side);
    } while (++i < counts.w);
  }
  if (area_has_rects && counts2.x > 0u) {
    uint i = 0u;
    do {
      RectLight l = rects[i];
      vec3 c = l.center_two_sided.xyz, hx = l.half_x.xyz, hy = l.half_y.xyz;
      bool two_sided = l.center_two_sided.w > 0.0;
      if (below_horizon(s, c, length(hx + hy))) continue;
      vec3 radiance = l.radiance.rgb * area_visibility(s, l.radiance.w, c, rect_extent(hx, hy, normalize(s.position - c)));
      added += diffuse_brdf * radiance * rect_irradiance(c, hx, hy, two_sided, s.position, s.normal);
      if (area_specular_ltc) {
        added += radiance * s.specular_albedo * ltc_rect_specular(c, hx, hy, two_sided, s.position, s.normal, s.view, ltc);
        continue;
      }
      RepresentativePoint rp = rect_specular_point(c, hx, hy, two_sided, s.position, r, s.alpha);
      vec3 normal = cross(hx, hy);
      float facing = abs(dot(normalize(normal), rp.direction));
      added += area_specular(s, rp, radiance, 4.0 * length(normal) * facing);
    } while (++i < counts2.x);
  }
  return added;
}

#endif
