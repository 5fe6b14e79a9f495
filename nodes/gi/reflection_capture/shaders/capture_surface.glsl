// gi.reflection_capture's raster capture: one opaque or alpha-tested mesh into a cube face, lit
// as the frame lights it (forward_shading.glsl). With LG_ALPHA_MASK defined (capture_masked.frag),
// fragments whose alpha is below the material's cutoff are discarded, as in the G-buffer.
#include "nodes/scene/forward_transparent/shaders/forward_shading.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  Draw d = draws[draw_index];
  MaterialSample m = sample_material(d);
  vec3 radiance = forward_radiance(d, m);
#ifdef LG_ALPHA_MASK
  // Last, so that every texture above is sampled with its derivatives from whole quads.
  if (m.base.a < d.alpha.x) discard;
#endif
  out_color = vec4(radiance, 1.0);
}
