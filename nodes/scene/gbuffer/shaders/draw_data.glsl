// One draw as the passes that rasterize the scene's meshes read it (std430; draw_constants.cpp
// fills it): the G-buffer's, scene.forward_transparent's and lighting.deferred's shadow maps.
#ifndef LG_DRAW_DATA_GLSL
#define LG_DRAW_DATA_GLSL

// The material's textures, in the order of MaterialTexture (draw_constants.h).
#define LG_BASE_COLOR_MAP 0
#define LG_METALLIC_ROUGHNESS_MAP 1
#define LG_NORMAL_MAP 2
#define LG_OCCLUSION_MAP 3
#define LG_EMISSIVE_MAP 4

struct Draw {
  mat4 world;
  mat4 previous_world;
  mat4 normal_matrix;  // inverse transpose of world's upper 3x3
  vec4 base_color;     // linear RGBA, multiplies the texture and the vertex colour
  vec4 material;       // perceptual roughness, metalness, normal scale (0: no normal map), occlusion strength
  vec4 alpha;          // x: alpha cutoff of MASK materials; y: the alpha below which light passes (shadow maps)
  vec4 emissive;       // rgb: emitted radiance, multiplies the emissive texture
  // Per texture two rows of its 2x3 uv transform; the first row's w is its texcoord set, the
  // second's 1 where the material has the texture.
  vec4 uv_transforms[10];
};

// The uv that texture `map` of draw `d` reads: its set of `texcoords` (set 0 in xy, set 1 in
// zw), through its transform.
vec2 draw_map_uv(Draw d, int map, vec4 texcoords) {
  vec4 row0 = d.uv_transforms[2 * map], row1 = d.uv_transforms[2 * map + 1];
  vec3 uv = vec3(row0.w > 0.5 ? texcoords.zw : texcoords.xy, 1.0);
  return vec2(dot(row0.xyz, uv), dot(row1.xyz, uv));
}

// Whether draw `d` has texture `map`: the same for the whole draw, so the branch on it is uniform.
bool draw_has_map(Draw d, int map) {
  return d.uv_transforms[2 * map + 1].w > 0.5;
}

#endif
