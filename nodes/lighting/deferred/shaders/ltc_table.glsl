// The LTC table of nodes/lighting/deferred/ltc_table.h (fitted by lumagraph-ltc-fit), read
// bilinearly as ltc_lookup does on the CPU. Include it after #define LG_LTC_BINDING: a uniform
// buffer there holds the table, one entry a vec4, filled from ltc_table_texels() (area_lights.glsl
// binds it at 22). A uniform block, not a storage buffer: lavapipe loads a storage buffer one
// lane at a time.
#ifndef LG_LTC_TABLE_GLSL
#define LG_LTC_TABLE_GLSL

const int LG_LTC_SIZE = 32;

layout(std140, binding = LG_LTC_BINDING) uniform Ltc { vec4 ltc_table[LG_LTC_SIZE * LG_LTC_SIZE]; };

vec4 ltc_entry(int i, int j) {
  return ltc_table[j * LG_LTC_SIZE + i];
}

vec4 ltc_lookup(float n_dot_v, float roughness) {
  const int last = LG_LTC_SIZE - 1;
  vec2 at = vec2(sqrt(1.0 - clamp(n_dot_v, 0.0, 1.0)), clamp(roughness, 0.0, 1.0)) * float(last);
  ivec2 i0 = min(ivec2(at), ivec2(last - 1));
  vec2 f = at - vec2(i0);
  vec4 low = mix(ltc_entry(i0.x, i0.y), ltc_entry(i0.x + 1, i0.y), f.x);
  vec4 high = mix(ltc_entry(i0.x, i0.y + 1), ltc_entry(i0.x + 1, i0.y + 1), f.x);
  return mix(low, high, f.y);
}

#endif
