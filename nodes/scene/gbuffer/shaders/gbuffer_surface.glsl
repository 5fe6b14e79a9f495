// The G-buffer's fragment stage (nodes/common/shaders/gbuffer.glsl). With LG_MATERIAL_MAPS
// defined, the glTF metal-rough material sampled with each texture's texcoord set, uv
// transform and sampler, the normal map in tangent space, and vertex colours; without, the
// material's factors alone (gbuffer_plain.frag: what draws without textures or vertex colours
// need, with fewer inputs to interpolate). With LG_ALPHA_MASK defined as well
// (gbuffer_masked.frag), fragments whose alpha is below the material's cutoff are discarded;
// the other variants have no discard, so that depth testing can happen before shading. The
// material's occlusion goes into the albedo target's alpha for lighting.ibl.
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/scene/gbuffer/shaders/draw.glsl"

layout(binding = 2) uniform sampler2D base_color_texture;          // sRGB
layout(binding = 3) uniform sampler2D metallic_roughness_texture;  // G roughness, B metalness
layout(binding = 4) uniform sampler2D normal_texture;              // tangent space, n * 0.5 + 0.5
layout(binding = 5) uniform sampler2D occlusion_texture;           // R

layout(location = 0) in vec3 world_normal;
layout(location = 2) in vec4 clip_now;
layout(location = 3) in vec4 clip_before;
#ifdef LG_MATERIAL_MAPS
layout(location = 1) in vec4 texcoords;
layout(location = 4) in vec3 surface_position;
layout(location = 5) in vec4 world_tangent;
layout(location = 6) in vec4 vertex_color;
#endif

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out vec2 out_material;
layout(location = 3) out vec2 out_motion;

#ifdef LG_MATERIAL_MAPS
// The uv that texture `map` of the draw reads: its set, through its transform.
vec2 map_uv(Draw d, int map) {
  vec4 row0 = d.uv_transforms[2 * map], row1 = d.uv_transforms[2 * map + 1];
  vec3 uv = vec3(row0.w > 0.5 ? texcoords.zw : texcoords.xy, 1.0);
  return vec2(dot(row0.xyz, uv), dot(row1.xyz, uv));
}

// Texture `map` at its uv, or `absent` where the material has none: the branch is the same for
// the whole draw, so untextured materials (the default world's) pay no texture fetch.
vec4 sample_map(Draw d, int map, sampler2D tex, vec4 absent) {
  return d.uv_transforms[2 * map + 1].w > 0.5 ? texture(tex, map_uv(d, map)) : absent;
}

// The normal map applied to the unit geometric normal n (of the front face).
vec3 mapped_normal(Draw d, vec3 n) {
  vec2 uv = map_uv(d, LG_NORMAL_MAP);
  vec3 t = world_tangent.xyz;
  float sign = world_tangent.w;
  if (dot(t, t) < 1e-12) {
    // No tangents in the mesh: the frame from how position and uv change across the pixel.
    // dp/dx = du/dx dp/du + dv/dx dp/dv, the same in y: solved for dp/du and dp/dv, whose
    // common scale (1 / det) is dropped but not its sign.
    vec3 dp_dx = dFdx(surface_position), dp_dy = dFdy(surface_position);
    vec2 duv_dx = dFdx(uv), duv_dy = dFdy(uv);
    float det_sign = duv_dx.x * duv_dy.y - duv_dx.y * duv_dy.x < 0.0 ? -1.0 : 1.0;
    t = (dp_dx * duv_dy.y - dp_dy * duv_dx.y) * det_sign;
    vec3 dp_dv = (dp_dy * duv_dx.x - dp_dx * duv_dy.x) * det_sign;
    sign = dot(cross(n, t), -dp_dv) < 0.0 ? -1.0 : 1.0;  // the bitangent points toward decreasing v
  }
  t -= n * dot(n, t);
  if (dot(t, t) < 1e-12) return n;  // no usable frame: the geometric normal
  t = normalize(t);
  vec3 b = cross(n, t) * sign;
  vec3 m = texture(normal_texture, uv).xyz * 2.0 - 1.0;
  m.xy *= d.material.z;
  vec3 mapped = t * m.x + b * m.y + n * m.z;
  return dot(mapped, mapped) > 1e-12 ? normalize(mapped) : n;
}

#endif

void main() {
  Draw d = draws[draw_index];
  vec3 n = normalize(world_normal);
#ifdef LG_MATERIAL_MAPS
  if (d.material.z != 0.0) n = mapped_normal(d, n);
  vec4 base = d.base_color * vertex_color * sample_map(d, LG_BASE_COLOR_MAP, base_color_texture, vec4(1.0));
  vec4 metal_rough = sample_map(d, LG_METALLIC_ROUGHNESS_MAP, metallic_roughness_texture, vec4(1.0));
  float occlusion = 1.0 + d.material.w * (sample_map(d, LG_OCCLUSION_MAP, occlusion_texture, vec4(1.0)).r - 1.0);
#else
  vec4 base = d.base_color, metal_rough = vec4(1.0);
  float occlusion = 1.0;
#endif
  if (!gl_FrontFacing) n = -n;  // a back face (double-sided, or culling off) shades its visible side
#ifdef LG_ALPHA_MASK
  // Last, so that every texture above is sampled with its derivatives from whole quads.
  if (base.a < d.alpha.x) discard;
#endif
  out_normal = vec4(encode_normal(n), 0.0);
  out_albedo = vec4(clamp(base.rgb, 0.0, 1.0), clamp(occlusion, 0.0, 1.0));
  out_material = clamp(d.material.xy * metal_rough.gb, 0.0, 1.0);
  vec2 uv_now = clip_now.xy / clip_now.w * 0.5;
  vec2 uv_before = clip_before.xy / max(clip_before.w, 1e-6) * 0.5;
  out_motion = uv_now - uv_before;
}
