#version 460
#extension GL_GOOGLE_include_directive : require
// scene.forward_transparent: one BLEND draw's fragment, shaded by forward_shading.glsl. Out:
// premultiplied radiance x alpha and alpha, alpha the base colour's (factor x texture x vertex
// colour), for "over" blending (ONE, ONE_MINUS_SRC_ALPHA). Behind the G-buffer's depth the
// fragment is discarded; nothing writes depth.
#include "nodes/scene/forward_transparent/shaders/forward_shading.glsl"

layout(binding = 19) uniform sampler2D scene_depth;  // the G-buffer's, reversed Z

layout(location = 0) out vec4 out_color;

void main() {
  Draw d = draws[draw_index];
  MaterialSample m = sample_material(d);
  vec3 radiance = forward_radiance(d, m);
  // Last, so that every texture above is sampled with its derivatives from whole quads. The
  // depth target may be smaller or larger than this one (the G-buffer's resolution_scale).
  ivec2 depth_texel = ivec2(gl_FragCoord.xy * camera.viewport.zw * vec2(textureSize(scene_depth, 0)));
  if (gl_FragCoord.z < texelFetch(scene_depth, depth_texel, 0).r) discard;  // reversed Z: behind
  float alpha = clamp(m.base.a, 0.0, 1.0);
  // Alpha is the share of the pixel the surface covers, so its emission is weighed by it too.
  out_color = vec4(radiance * alpha, alpha);
}
