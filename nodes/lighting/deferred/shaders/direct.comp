#version 460
#extension GL_GOOGLE_include_directive : require
// Directional and point lights on every G-buffer texel, with the shadow map for the first
// shadow-casting directional light; writes (and so clears) the node's output.
#include "nodes/lighting/deferred/shaders/surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 5) uniform sampler2D shadow_map;
layout(binding = 6, rgba16f) uniform writeonly image2D color;
layout(std430, binding = 7) readonly buffer Directional { DirectionalLight directional[]; };
layout(std430, binding = 8) readonly buffer Points { PointLight points[]; };

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

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(color)))) return;
  Surface s;
  vec3 radiance = vec3(0.0);
  if (read_surface(texel, s)) {
    for (uint i = 0; i < counts.x; ++i) {
      DirectionalLight light = directional[i];
      float visibility = light.direction.w > 0.0 ? sun_visibility(s) : 1.0;
      radiance += brdf_cosine(s, -light.direction.xyz) * light.irradiance.rgb * visibility;
    }
    for (uint i = 0; i < counts.y; ++i) {
      PointLight light = points[i];
      vec3 to_light = light.position_range.xyz - s.position;
      float d2 = max(dot(to_light, to_light), 1e-8);
      float range = light.position_range.w;
      // A smooth window to 0 at the range (Karis 2013), so a cut-off light shows no edge.
      float window = range > 0.0 ? pow(clamp(1.0 - pow(d2 / (range * range), 2.0), 0.0, 1.0), 2.0) : 1.0;
      radiance += brdf_cosine(s, to_light * inversesqrt(d2)) * light.intensity.rgb * (window / d2);
    }
  }
  imageStore(color, texel, vec4(finite_or_zero(radiance), 1.0));
}
