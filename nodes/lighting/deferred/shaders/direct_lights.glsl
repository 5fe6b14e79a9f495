// Directional, point and spot lights on a surface, with the shadow map of the first
// shadow-casting directional light and the local shadow atlas of the point and spot lights the
// budget gave one (each skipped where its constant says it was not drawn): lighting.deferred's
// direct pass, and scene.forward_transparent's surfaces. Bindings 10 to 15; the constants at 0
// (lights.glsl).
#ifndef LG_DIRECT_LIGHTS_GLSL
#define LG_DIRECT_LIGHTS_GLSL

#include "nodes/common/shaders/brdf.glsl"
#include "nodes/common/shaders/light_falloff.glsl"
#include "nodes/lighting/deferred/shaders/lights.glsl"
#include "nodes/lighting/deferred/shaders/local_shadow_atlas.glsl"

layout(binding = 10) uniform sampler2D shadow_map;
layout(std140, binding = 11) uniform Directional { DirectionalLight directional[LG_MAX_LIGHTS]; };
layout(std140, binding = 12) uniform Points { PointLight points[LG_MAX_LIGHTS]; };
layout(std140, binding = 13) uniform Spots { SpotLight spots[LG_MAX_LIGHTS]; };

// 3x3 percentage-closer filtering: the fraction of taps nearer the light than p is shadowed.
// Reversed depth: a larger stored value is nearer the light.
float sun_visibility(Surface s) {
  if (shadow.y == 0.0) return 1.0;
  vec3 offset_p = s.position + s.normal * shadow.z;
  vec4 clip = shadow_from_world * vec4(offset_p, 1.0);
  vec2 uv = clip.xy * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  ivec2 size = textureSize(shadow_map, 0);
  ivec2 center = ivec2(uv * vec2(size));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      ivec2 t = clamp(center + ivec2(x, y), ivec2(0), size - 1);
      lit += texelFetch(shadow_map, t, 0).r > clip.z + shadow.w ? 0.0 : 1.0;
    }
  return lit / 9.0;
}

// The same filter and bias for a point or spot light's view: a normal offset of 1.5 texels and
// a depth bias of two, in texels of the view at p's distance (a perspective map's texels grow
// with distance). `first` is the light's first view, `count` 1 or 6 (cube faces +X, -X, +Y,
// -Y, +Z, -Z: the one of p's major axis from the light).
float local_visibility(Surface s, vec3 light_position, float first, float count) {
  if (!local_shadows_drawn || first < 0.0 || local_shadow.x == 0.0) return 1.0;
  ShadowView view = view_toward(first, count, s.position - light_position);
  float distance = (view.clip_from_world * vec4(s.position, 1.0)).w;
  if (distance <= local_shadow.y) return 1.0;  // behind the light or nearer than its map sees
  float texel = view.tile.w * distance;
  vec4 clip = view.clip_from_world * vec4(s.position + s.normal * (1.5 * texel), 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;  // outside a spot's cone
  // Reversed depth: a stored value above this is nearer the light than p less the bias.
  float reference = local_shadow.y / max(clip.w - 2.0 * texel, 1e-6);
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texelFetch(local_shadow_atlas, atlas_texel(view, clip, ivec2(x, y)), 0).r > reference ? 0.0 : 1.0;
  return lit / 9.0;
}

// A point light's radiance toward the eye: intensity over distance squared, windowed to 0 at
// its range (light_falloff.glsl).
vec3 punctual(Surface s, vec4 position_range, vec3 intensity) {
  vec3 to_light = position_range.xyz - s.position;
  float d2 = max(dot(to_light, to_light), 1e-8);
  float window = light_range_window(d2, position_range.w);
  return brdf_cosine(s, to_light * inversesqrt(d2)) * intensity * (window / d2);
}

// Radiance toward the eye from every directional, point and spot light.
// The loops are do-whiles: lavapipe (Mesa 22.3) runs a loop's body under the lanes' mask and
// leaves only when no lane is left, so a `for`, whose exit test comes first, runs its body once
// more, all lanes masked off, after the last light (the sun's 3x3 filter ran twice a pixel). A
// do-while tests at the end and runs n bodies for n lights; the `if` around it runs its body
// masked when n is 0, as the `for` did.
vec3 direct_radiance(Surface s) {
  vec3 radiance = vec3(0.0);
  if (counts.x > 0u) {
    uint i = 0u;
    do {
      DirectionalLight light = directional[i];
      float visibility = light.direction.w > 0.0 ? sun_visibility(s) : 1.0;
      radiance += brdf_cosine(s, -light.direction.xyz) * light.irradiance.rgb * visibility;
    } while (++i < counts.x);
  }
  if (counts.y > 0u) {
    uint i = 0u;
    do {
      PointLight light = points[i];
      float visibility = local_visibility(s, light.position_range.xyz, light.intensity.w, 6.0);
      radiance += punctual(s, light.position_range, light.intensity.rgb * visibility);
    } while (++i < counts.y);
  }
  if (counts2.y > 0u) {
    uint i = 0u;
    do {
      SpotLight light = spots[i];
      vec3 l = normalize(light.position_range.xyz - s.position);
      // glTF KHR_lights_punctual's falloff: the square of a linear ramp in the cosine of the
      // angle to the axis, 0 at the outer cone and 1 from the inner cone in.
      float ramp = clamp(dot(light.direction_angle_scale.xyz, -l) * light.direction_angle_scale.w +
                             light.intensity_angle_offset.w, 0.0, 1.0);
      float visibility = local_visibility(s, light.position_range.xyz, light.shadow.x, light.shadow.y);
      radiance += punctual(s, light.position_range, light.intensity_angle_offset.rgb * (ramp * ramp * visibility));
    } while (++i < counts2.y);
  }
  return radiance;
}

#endif
