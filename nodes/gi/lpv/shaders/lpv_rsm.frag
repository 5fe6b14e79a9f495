#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's reflective shadow map texel: the surface's position, its normal turned to face the
// light (the map draws both sides of every face, as the shadow map does), and the flux it
// reflects per m^2 of the light's beam: diffuse colour (base colour x vertex colour x
// (1 - metalness); textures are not read) x the light's irradiance. Every power through the
// texel's beam lands on the surface whatever its slope, so the slope does not enter. A texel with
// anything non-finite is left invalid (a = 0).
#include "nodes/common/shaders/finite.glsl"
#include "nodes/lighting/deferred/shaders/shadow_draw.glsl"

layout(std140, binding = 1) uniform LightBlock {
  vec4 light_direction;   // xyz: the way the light travels
  vec4 light_irradiance;  // rgb, W/m^2
};

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec3 vertex_color;
layout(location = 0) out vec4 out_position;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_flux;

void main() {
  Draw d = this_draw;
  // A degenerate vertex normal: the face's own, from the position's screen derivatives (taken
  // outside any branch, where derivatives are defined).
  vec3 face = cross(dFdx(world_position), dFdy(world_position));
  vec3 n = world_normal;
  float len = length(n);
  n = len > 1e-6 ? n / len : face;
  len = length(n);
  n = len > 1e-12 ? n / len : -light_direction.xyz;
  if (dot(n, light_direction.xyz) > 0.0) n = -n;
  vec3 albedo = clamp(d.base_color.rgb * vertex_color * (1.0 - d.material.y), 0.0, 1.0);
  vec3 flux = albedo * light_irradiance.rgb;
  bool ok = all_finite(vec4(world_position, 0.0)) && all_finite(vec4(n, 0.0)) && all_finite(vec4(flux, 0.0));
  out_position = ok ? vec4(world_position, 1.0) : vec4(0.0);
  out_normal = ok ? vec4(n, 0.0) : vec4(0.0);
  out_flux = ok ? vec4(flux, 0.0) : vec4(0.0);
}
