#version 460
#extension GL_GOOGLE_include_directive : require
// Writes one surface sample into the G-buffer (nodes/common/shaders/gbuffer.glsl).
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/scene/gbuffer/shaders/draw.glsl"

layout(binding = 2) uniform sampler2D base_color_texture;

layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec4 clip_now;
layout(location = 3) in vec4 clip_before;

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out vec2 out_material;
layout(location = 3) out vec2 out_motion;

void main() {
  Draw d = draws[draw_index];
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;  // two-sided surfaces (culling off) shade their visible side
  out_normal = vec4(encode_normal(n), 0.0);
  out_albedo = clamp(d.base_color * texture(base_color_texture, texcoord), 0.0, 1.0);
  out_material = clamp(d.material.xy, 0.0, 1.0);
  vec2 uv_now = clip_now.xy / clip_now.w * 0.5;
  vec2 uv_before = clip_before.xy / max(clip_before.w, 1e-6) * 0.5;
  out_motion = uv_now - uv_before;
}
