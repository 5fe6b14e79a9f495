#version 460
#extension GL_GOOGLE_include_directive : require
// Depth from a light for MASK and BLEND draws: where the alpha (base colour factor x texture x
// vertex colour, as the G-buffer's alpha test and the path tracer take it) is below the draw's
// light cutoff, light passes and no depth is written.
#include "nodes/lighting/deferred/shaders/shadow_draw.glsl"

layout(binding = 1) uniform sampler2D base_color_texture;

layout(location = 0) in vec4 texcoords;
layout(location = 1) in float vertex_alpha;

void main() {
  Draw d = this_draw;
  float alpha = d.base_color.a * vertex_alpha;
  if (draw_has_map(d, LG_BASE_COLOR_MAP))
    alpha *= texture(base_color_texture, draw_map_uv(d, LG_BASE_COLOR_MAP, texcoords)).a;
  if (alpha < d.alpha.y) discard;
}
