// The G-buffer's fragment stage (nodes/common/shaders/gbuffer.glsl): the draw's material
// (gbuffer_material.glsl, with its textures where LG_MATERIAL_MAPS is defined). With
// LG_ALPHA_MASK defined as well (gbuffer_masked.frag), fragments whose alpha is below the
// material's cutoff are discarded; the other variants have no discard, so that depth testing
// can happen before shading. The material's occlusion goes into the albedo target's alpha for
// lighting.ibl; the emitted radiance into its own target, which lighting.deferred adds.
#define LG_DRAW_BLOCK  // the draw's constants as draw.glsl's uniform block
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/scene/gbuffer/shaders/gbuffer_material.glsl"

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out vec2 out_material;
layout(location = 3) out vec2 out_motion;
layout(location = 4) out vec4 out_emissive;

void main() {
  Draw d = this_draw;
  MaterialSample m = sample_material(d);
#ifdef LG_ALPHA_MASK
  // Last, so that every texture above is sampled with its derivatives from whole quads.
  if (m.base.a < d.alpha.x) discard;
#endif
  out_normal = vec4(encode_normal(m.normal), 0.0);
  out_albedo = vec4(clamp(m.base.rgb, 0.0, 1.0), clamp(m.occlusion, 0.0, 1.0));
  out_material = clamp(d.material.xy * m.metal_rough.gb, 0.0, 1.0);
  vec2 uv_now = clip_now.xy / clip_now.w * 0.5;
  vec2 uv_before = clip_before.xy / max(clip_before.w, 1e-6) * 0.5;
  // clip_now is jittered (post.taa), clip_before never is: the jitter's uv offset comes out, so
  // reprojection follows the scene only. With no jitter it subtracts 0, bit for bit the same.
  out_motion = uv_now - uv_before - camera.jitter.xy * 0.5;
  out_emissive = vec4(m.emission, 0.0);
}
