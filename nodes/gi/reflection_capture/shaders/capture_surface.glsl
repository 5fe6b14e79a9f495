// The raster captures (gi.reflection_capture's cube faces, gi.planar_reflection's mirrored view):
// one opaque or alpha-tested mesh lit as the frame lights it (forward_shading.glsl). With
// LG_ALPHA_MASK defined (capture_masked.frag), fragments whose alpha is below the material's
// cutoff are discarded, as in the G-buffer. Fragments behind the settings' clip plane (a mirror's
// back) are not drawn; alpha is 1, or the distance to the camera where the settings ask for it.
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
