// Soft shadows of sphere, tube and rectangle lights from their cube maps in the local shadow
// atlas, percentage-closer soft shadows (Fernando 2005) taken in directions from the light's
// centre, so the filter crosses cube faces freely:
//   1. blocker search: D itself and a fixed pattern of `local_shadow.z` directions D + s, s over
//      the light's extent across D (D from the light's centre to the shaded point), finds the
//      blockers that hide part of the light (all of them from half way to the receiver on);
//   2. their mean depth z along D gives the penumbra's scale k = (d - z) / z, d = |D|
//      (penumbra width = light size x (d_receiver - d_blocker) / d_blocker);
//   3. the same pattern, D + k s, is tested against the map: the fraction not blocked.
// D + k s is where the ray from the light's point centre + s to the shaded point crosses the
// blockers' depth. Each tap compares the map with where its ray meets the receiver's tangent
// plane (not with d), so a tilted receiver does not shadow itself; bias as the point lights'
// (direct_lights.glsl): a normal offset of 1.5 texels and a depth bias of two.
#ifndef LG_AREA_SHADOWS_GLSL
#define LG_AREA_SHADOWS_GLSL


#include "nodes/common/shaders/brdf.glsl"
#include "nodes/lighting/deferred/shaders/local_shadow_atlas.glsl"

// What the pattern spreads over, across the direction from the light: s = u x + v y with
// (u, v) in the unit disk or the unit square.
struct LightExtent {
  vec3 x, y;
  bool square;
};

vec3 across(vec3 v, vec3 w) {
  return v - w * dot(v, w);
}

vec3 any_perpendicular(vec3 w) {
  return normalize(abs(w.x) < 0.9 ? cross(w, vec3(1.0, 0.0, 0.0)) : cross(w, vec3(0.0, 1.0, 0.0)));
}

// A sphere seen along unit w is a disk of its radius.
LightExtent sphere_extent(float radius, vec3 w) {
  vec3 t = any_perpendicular(w);
  return LightExtent(radius * t, radius * cross(w, t), false);
}

// A capsule seen along w: the rectangle around its segment's shadow across w, grown by the radius.
LightExtent tube_extent(vec3 end0, vec3 end1, float radius, vec3 w) {
  vec3 half_axis = across(0.5 * (end1 - end0), w);
  float len = length(half_axis);
  vec3 along = len > 1e-6 * radius ? half_axis / len : any_perpendicular(w);
  return LightExtent(half_axis + radius * along, radius * cross(w, along), true);
}

// A rectangle seen along w: its half sides across w.
LightExtent rect_extent(vec3 half_x, vec3 half_y, vec3 w) {
  return LightExtent(across(half_x, w), across(half_y, w), true);
}

// Tap i of n, in pairs mirrored through the centre (so the pattern's mean is the light's
// centre, and the shadow does not shift): a Vogel spiral of n / 2 points in the unit disk, or
// the R2 low-discrepancy lattice (Roberts 2018) in the unit square. An odd n's last tap is the
// centre.
vec2 extent_tap(uint i, uint n, bool square) {
  uint pairs = n / 2u, j = i / 2u;
  if (j >= pairs) return vec2(0.0);
  float sign = (i & 1u) == 0u ? 1.0 : -1.0;
  if (square) return sign * (2.0 * fract(vec2(0.5) + float(j) * vec2(0.7548776662, 0.5698402910)) - 1.0);
  float angle = float(j) * 2.3999632;  // the golden angle
  return sign * sqrt((float(j) + 0.5) / float(pairs)) * vec2(cos(angle), sin(angle));
}

// One tap, along D + `offset` from the light's centre: 0 when its ray misses the receiver's
// plane (it is left out: the part of the light it stands for is low over the surface's
// horizon, where it lights little), 1 when the map holds nothing nearer than the plane less the bias, 2 when it holds
// a blocker, whose depth along unit `w` it sets.
int area_shadow_tap(float first, vec3 center, vec3 D, vec3 w, Surface s, float texel, vec3 offset, out float blocker) {
  vec3 dir = normalize(D + offset);
  float cosine = dot(s.normal, dir);
  float t = cosine != 0.0 ? dot(s.normal, D) / cosine : -1.0;  // along dir to the receiver's plane
  blocker = 0.0;
  if (t <= 0.0) return 0;
  ShadowView view = view_toward(first, 6.0, dir);
  vec4 clip = view.clip_from_world * vec4(center + dir, 1.0);
  float stored = texelFetch(local_shadow_atlas, atlas_texel(view, clip, ivec2(0)), 0).r;
  // near / stored is the depth along the face's axis, clip.w = dir's component along it.
  float along = local_shadow.y / max(stored, 1e-30) / clip.w;
  if (along >= t * (1.0 - 2.0 * texel)) return 1;
  blocker = along * dot(dir, w);
  return 2;
}

// The fraction of an area light (centre `center`, `extent` across the direction to the
// surface) that the surface sees past the light's map, or 1 when the light has none
// (`first` < 0) or the atlas was not drawn.
float area_visibility(Surface s, float first, vec3 center, LightExtent extent) {
  if (!local_shadows_drawn || first < 0.0 || local_shadow.x == 0.0) return 1.0;
  float texel = views[int(first)].tile.w;  // at distance 1; every face of a cube has the same
  vec3 to_surface = s.position - center;
  float d0 = length(to_surface);
  if (d0 <= local_shadow.y) return 1.0;  // nearer than the map sees
  vec3 D = to_surface + s.normal * (1.5 * texel * d0);
  float d = length(D);
  vec3 w = D / d;
  uint n = uint(local_shadow.z);

  // The search's taps, and one along D itself: a blocker at depth z along tap D + s hides the
  // light's point centre + s z / (d - z), so it counts only where that point is on the light
  // (z <= d / (1 + r), r the tap's reach in the disk or square). Else a wall near the light
  // but beside the receiver's line of sight would widen the penumbra, and past a corner the
  // filter would see the wall's far side, which lies in the receiver's plane, as lit.
  //
  // Both loops are do-whiles (n >= 1): lavapipe leaves a loop only when no lane is left in it,
  // so a `for` ran one more tap after the last with every lane masked off. Lanes that return
  // before the filter leave its loop, which ends at once where all of them did.
  float blocker_sum = 0.0, blockers = 0.0, blocker;
  uint i = 0u;
  do {
    vec2 uv = i < n ? extent_tap(i, n, extent.square) : vec2(0.0);
    float reach = extent.square ? max(abs(uv.x), abs(uv.y)) : length(uv);
    if (area_shadow_tap(first, center, D, w, s, texel, (uv.x * extent.x + uv.y * extent.y), blocker) == 2 &&
        blocker * (1.0 + reach) <= d) {
      blocker_sum += blocker;
      blockers += 1.0;
    }
  } while (++i <= n);
  if (blockers == 0.0) return 1.0;
  float z = blocker_sum / blockers;
  float k = max(d - z, 0.0) / max(z, local_shadow.y);

  float lit = 0.0, taps = 0.0;
  i = 0u;
  do {
    vec2 uv = extent_tap(i, n, extent.square);
    int tap = area_shadow_tap(first, center, D, w, s, texel, k * (uv.x * extent.x + uv.y * extent.y), blocker);
    taps += tap > 0 ? 1.0 : 0.0;
    lit += tap == 1 ? 1.0 : 0.0;
  } while (++i < n);
  return taps > 0.0 ? lit / taps : 1.0;
}

#endif
