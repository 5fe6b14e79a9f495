#version 460
#extension GL_GOOGLE_include_directive : require
// scene.forward_transparent: one BLEND draw's fragment (vertex stage: the G-buffer's
// gbuffer.vert), its material sampled as the G-buffer samples it (gbuffer_material.glsl) and
// lit as opaque surfaces are: lighting.deferred's directional, point, spot (direct_lights.glsl)
// and area lights (area_lights.glsl), and lighting.ibl's environment (ibl_environment.glsl)
// with the material's own occlusion, plus its emission. Out: premultiplied radiance x alpha and alpha, alpha the
// base colour's (factor x texture x vertex colour), for "over" blending (ONE,
// ONE_MINUS_SRC_ALPHA). Behind the G-buffer's depth the fragment is discarded; nothing writes
// depth. Shadow maps are not read: the constants say none was drawn.
#include "nodes/common/shaders/finite.glsl"
#include "nodes/lighting/deferred/shaders/area_lights.glsl"
#include "nodes/lighting/deferred/shaders/direct_lights.glsl"
#include "nodes/lighting/ibl/shaders/ibl_environment.glsl"
// lights.glsl's constants at binding 0 start with the camera the vertex stage reads there.
#define LG_CAMERA_DECLARED
#define LG_MATERIAL_MAPS
#include "nodes/scene/gbuffer/shaders/gbuffer_material.glsl"

layout(binding = 19) uniform sampler2D scene_depth;  // the G-buffer's, reversed Z
layout(std140, binding = 20) uniform Settings {
  uint flags;  // 1: image-based light, 2: its diffuse from SH (else the irradiance map)
  float intensity;
};

layout(location = 0) out vec4 out_color;

void main() {
  Draw d = draws[draw_index];
  MaterialSample m = sample_material(d);
  vec2 metal_rough = clamp(d.material.xy * m.metal_rough.gb, 0.0, 1.0);
  float roughness = metal_rough.x, metalness = metal_rough.y;
  vec3 albedo = clamp(m.base.rgb, 0.0, 1.0);
  Surface s = make_surface(surface_position, m.normal, camera.position.xyz, albedo, roughness, metalness);
  vec3 radiance = direct_radiance(s) + area_radiance(s);
  if ((flags & 1u) != 0u)
    radiance += intensity * environment_light(s.normal, s.view, s.diffuse_color, s.f0, roughness,
                                              clamp(m.occlusion, 0.0, 1.0), (flags & 2u) != 0u);
  // Last, so that every texture above is sampled with its derivatives from whole quads. The
  // depth target may be smaller or larger than this one (the G-buffer's resolution_scale).
  ivec2 depth_texel = ivec2(gl_FragCoord.xy * camera.viewport.zw * vec2(textureSize(scene_depth, 0)));
  if (gl_FragCoord.z < texelFetch(scene_depth, depth_texel, 0).r) discard;  // reversed Z: behind
  float alpha = clamp(m.base.a, 0.0, 1.0);
  // Alpha is the share of the pixel the surface covers, so its emission is weighed by it too.
  out_color = vec4(finite_or_zero(radiance + m.emission) * alpha, alpha);
}
