// The glTF metal-rough material of one draw at a fragment, as the G-buffer stores it and as
// scene.forward_transparent lights it. With LG_MATERIAL_MAPS defined, the material sampled with
// each texture's texcoord set, uv transform and sampler, the normal map in tangent space, and
// vertex colours; without, the material's factors alone (what draws without textures or vertex
// colours need, with fewer inputs to interpolate). Inputs are gbuffer_vertex.glsl's outputs.
#ifndef LG_GBUFFER_MATERIAL_GLSL
#define LG_GBUFFER_MATERIAL_GLSL

#include "nodes/scene/gbuffer/shaders/draw.glsl"

layout(binding = 2) uniform sampler2D base_color_texture;          // sRGB
layout(binding = 3) uniform sampler2D metallic_roughness_texture;  // G roughness, B metalness
layout(binding = 4) uniform sampler2D normal_texture;              // tangent space, n * 0.5 + 0.5
layout(binding = 5) uniform sampler2D occlusion_texture;           // R
layout(binding = 21) uniform sampler2D emissive_texture;           // sRGB (material_textures.h)

layout(location = 0) in vec3 world_normal;
layout(location = 2) in vec4 clip_now;
layout(location = 3) in vec4 clip_before;
#ifdef LG_MATERIAL_MAPS
layout(location = 1) in vec4 texcoords;
layout(location = 4) in vec3 surface_position;
layout(location = 5) in vec4 world_tangent;
layout(location = 6) in vec4 vertex_color;
#endif

#ifdef LG_MATERIAL_MAPS
// The uv that texture `map` of the draw reads: its set, through its transform.
vec2 map_uv(Draw d, int map) {
  return draw_map_uv(d, map, texcoords);
}

// Texture `map` at its uv, or `absent` where the material has none: the branch is the same for
// the whole draw, so untextured materials (the default world's) pay no texture fetch.
vec4 sample_map(Draw d, int map, sampler2D tex, vec4 absent) {
  return draw_has_map(d, map) ? texture(tex, map_uv(d, map)) : absent;
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

// The material at this fragment: the shading normal facing the viewer's side, base colour
// with alpha (factor x texture x vertex colour), metallic-roughness texel, occlusion and
// emitted radiance.
struct MaterialSample {
  vec3 normal;
  vec4 base;
  vec4 metal_rough;  // g: roughness, b: metalness, to multiply the factors
  float occlusion;
  vec3 emission;
};

MaterialSample sample_material(Draw d) {
  MaterialSample m;
  m.normal = normalize(world_normal);
#ifdef LG_MATERIAL_MAPS
  if (d.material.z != 0.0) m.normal = mapped_normal(d, m.normal);
  m.base = d.base_color * vertex_color * sample_map(d, LG_BASE_COLOR_MAP, base_color_texture, vec4(1.0));
  m.metal_rough = sample_map(d, LG_METALLIC_ROUGHNESS_MAP, metallic_roughness_texture, vec4(1.0));
  m.occlusion = 1.0 + d.material.w * (sample_map(d, LG_OCCLUSION_MAP, occlusion_texture, vec4(1.0)).r - 1.0);
  m.emission = d.emissive.rgb * sample_map(d, LG_EMISSIVE_MAP, emissive_texture, vec4(1.0)).rgb;
#else
  m.base = d.base_color;
  m.metal_rough = vec4(1.0);
  m.occlusion = 1.0;
  m.emission = d.emissive.rgb;
#endif
  if (!gl_FrontFacing) m.normal = -m.normal;  // a back face (double-sided, or culling off) shades its visible side
  return m;
}

#endif
