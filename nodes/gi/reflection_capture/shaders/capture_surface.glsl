// The raster captures (gi.reflection_capture's cube faces, gi.planar_reflection's mirrored view):
// one opaque or alpha-tested mesh lit as the frame lights it (forward_shading.glsl), with
// gi.irradiance_volume's irradiance where its probes are linked (probe_volume.glsl's lookup, as
// the volume's own lookup gives it to the frame's lighting.ibl; the specialization constants
// say whether and how). With LG_ALPHA_MASK defined (capture_masked.frag), fragments whose alpha
// is below the material's cutoff are discarded, as in the G-buffer. Fragments behind the
// settings' clip plane (a mirror's back) are not drawn; alpha is 1, or the distance to the camera
// where the settings ask for it.
#define LG_PROBE_VOLUME_BINDING 23
#define LG_PROBE_RECORD_BINDING 24
#define LG_PROBE_IRRADIANCE_BINDING 25
#define LG_PROBE_DISTANCE_BINDING 26
#include "nodes/gi/irradiance_volume/shaders/probe_volume.glsl"
#include "nodes/scene/forward_transparent/shaders/forward_settings.glsl"

// After the lights' constants 0 and 1 (local_shadow_atlas.glsl, area_lights.glsl), which the
// captures leave at their defaults (raster_capture.cpp).
layout(constant_id = 2) const bool probe_volume = false;
layout(constant_id = 3) const uint probe_representation = LG_PROBE_OCTAHEDRAL;  // ProbeRepresentation
layout(constant_id = 4) const bool probe_visibility = true;

// The volumes' irradiance (rgb, W/m^2) and coverage (a) at surface point p with normal n seen
// from `eye` (the capture's camera); none without a linked volume.
vec4 capture_volume_irradiance(vec3 p, vec3 n, vec3 eye) {
  if (!probe_volume) return vec4(0.0);
  ProbeLookup s = ProbeLookup(probe_representation, probe_visibility, volume_normal_bias, volume_view_bias);
  return lookup_volumes(int(volume_count), p, n, eye, s);
}
#define LG_FORWARD_VOLUME_IRRADIANCE capture_volume_irradiance

#include "nodes/scene/forward_transparent/shaders/forward_shading.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  if (dot(clip_plane, vec4(surface_position, 1.0)) < 0.0) discard;
  Draw d = draws[draw_index];
  MaterialSample m = sample_material(d);
  vec3 radiance = forward_radiance(d, m);
#ifdef LG_ALPHA_MASK
  // Last, so that every texture above is sampled with its derivatives from whole quads.
  if (m.base.a < d.alpha.x) discard;
#endif
  // The distance at most half float's largest, the sky's: past it the target would hold infinity.
  float eye_distance = min(distance(surface_position, camera.position.xyz), 65504.0);
  out_color = vec4(radiance, (flags & 4u) != 0u ? eye_distance : 1.0);
}
