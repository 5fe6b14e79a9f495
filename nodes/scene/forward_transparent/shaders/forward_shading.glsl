// A mesh's fragment lit as lighting.deferred and lighting.ibl light opaque surfaces, for the
// forward passes that shade while they rasterize: scene.forward_transparent's blended draws and
// gi.reflection_capture's cube faces. Its material sampled as the G-buffer samples it
// (gbuffer_material.glsl; vertex stage: the G-buffer's gbuffer.vert), lit by the directional,
// point and spot lights (direct_lights.glsl), the area lights (area_lights.glsl) and the
// environment (ibl_environment.glsl) with the material's own occlusion, plus its emission.
// Shadow maps are not read: the constants say none was drawn.
#ifndef LG_FORWARD_SHADING_GLSL
#define LG_FORWARD_SHADING_GLSL

#include "nodes/common/shaders/finite.glsl"
#include "nodes/lighting/deferred/shaders/area_lights.glsl"
#include "nodes/lighting/deferred/shaders/direct_lights.glsl"
#include "nodes/lighting/ibl/shaders/ibl_environment.glsl"
// lights.glsl's constants at binding 0 start with the camera the vertex stage reads there.
#define LG_CAMERA_DECLARED
#define LG_MATERIAL_MAPS
#include "nodes/scene/gbuffer/shaders/gbuffer_material.glsl"

#include "nodes/scene/forward_transparent/shaders/forward_settings.glsl"

// The radiance the fragment's surface sends toward the camera (finite), its material `m`.
vec3 forward_radiance(Draw d, MaterialSample m) {
  vec2 metal_rough = clamp(d.material.xy * m.metal_rough.gb, 0.0, 1.0);
  float roughness = metal_rough.x, metalness = metal_rough.y;
  vec3 albedo = clamp(m.base.rgb, 0.0, 1.0);
  Surface s = make_surface(surface_position, m.normal, camera.position.xyz, albedo, roughness, metalness);
  share_energy(s, brdf_albedo_lookup(max(dot(s.normal, s.view), 1e-4), roughness));
  vec3 radiance = direct_radiance(s) + area_radiance(s);
  if ((flags & 1u) != 0u)
    radiance += intensity * environment_light(s.normal, s.view, albedo * (1.0 - metalness), s.f0, roughness,
                                              clamp(m.occlusion, 0.0, 1.0), (flags & 2u) != 0u);
  return finite_or_zero(radiance + m.emission);
}

#endif
