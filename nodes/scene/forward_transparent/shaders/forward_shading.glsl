// A mesh's fragment lit as lighting.deferred and lighting.ibl light opaque surfaces, for the
// forward passes that shade while they rasterize: scene.forward_transparent's blended draws and
// gi.reflection_capture's cube faces. Its material sampled as the G-buffer samples it
// (gbuffer_material.glsl; vertex stage: the G-buffer's gbuffer.vert), lit by the directional,
// point and spot lights (direct_lights.glsl), the area lights (area_lights.glsl) and the
// environment (ibl_environment.glsl) with the material's own occlusion, plus its emission; an
// includer may add a probe volume's irradiance (forward_radiance()).
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

// The radiance the fragment's surface sends toward the camera (finite), its material `m`. An
// includer that defines LG_FORWARD_VOLUME_IRRADIANCE(position, normal, eye) as a function giving
// a probe volume's irradiance (rgb, W/m^2) and coverage (a) has the environment's diffuse
// irradiance mixed toward the volume's by the coverage, as lighting.ibl mixes it toward
// gi.irradiance_volume's (the raster captures: capture_surface.glsl).
vec3 forward_radiance(Draw d, MaterialSample m) {
  vec2 metal_rough = clamp(d.material.xy * m.metal_rough.gb, 0.0, 1.0);
  float roughness = metal_rough.x, metalness = metal_rough.y;
  vec3 albedo = clamp(m.base.rgb, 0.0, 1.0);
  Surface s = make_surface(surface_position, m.normal, camera.position.xyz, albedo, roughness, metalness);
  share_energy(s, brdf_albedo_lookup(max(dot(s.normal, s.view), 1e-4), roughness));
  vec3 radiance = direct_radiance(s) + area_radiance(s);
  bool environment = (flags & 1u) != 0u;
  vec3 irradiance_over_pi =
      environment ? intensity * environment_irradiance_over_pi(s.normal, (flags & 2u) != 0u) : vec3(0.0);
  bool diffuse_light = environment;
#ifdef LG_FORWARD_VOLUME_IRRADIANCE
  vec4 volume = LG_FORWARD_VOLUME_IRRADIANCE(surface_position, s.normal, camera.position.xyz);
  irradiance_over_pi = mix(irradiance_over_pi, volume.rgb / LG_SH_PI, clamp(volume.a, 0.0, 1.0));
  diffuse_light = diffuse_light || volume.a > 0.0;
#endif
  if (diffuse_light) {
    float occlusion = clamp(m.occlusion, 0.0, 1.0);
    vec2 scale_bias = dfg_scale_bias(clamp(dot(s.normal, s.view), 1e-4, 1.0), roughness);
    radiance += image_based_diffuse(albedo * (1.0 - metalness), s.f0, scale_bias, irradiance_over_pi, vec3(occlusion));
    if (environment) radiance += intensity * environment_specular(s.normal, s.view, s.f0, roughness, occlusion, scale_bias);
  }
  return finite_or_zero(radiance + m.emission);
}

#endif
