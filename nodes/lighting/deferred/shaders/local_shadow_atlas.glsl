// The local shadow atlas (local_shadows.h) as the direct and area passes read it: the depth
// atlas at binding 14, its views at 15, and which view of a light's one or six looks toward a
// direction. Depth is stored as near / distance along the view (reversed Z), 0 where nothing
// was drawn.
#ifndef LG_LOCAL_SHADOW_ATLAS_GLSL
#define LG_LOCAL_SHADOW_ATLAS_GLSL

#include "nodes/lighting/deferred/shaders/lights.glsl"

// Specialized false by lighting.deferred's passes when no view was drawn this frame, so the
// compiler drops every atlas lookup (lavapipe's code for the filters costs time even where the
// constants skip them); left true elsewhere, where local_shadow.x says at run time.
layout(constant_id = 0) const bool local_shadows_drawn = true;

layout(binding = 14) uniform sampler2D local_shadow_atlas;
// Views a frame draws at most: six for each of the 16 lights the schema's shadow_budget allows
// (light_buffers.h's kMaxShadowViews). A uniform block, not a storage buffer: lavapipe loads a
// storage buffer one lane at a time, and a soft shadow reads a view for each of its taps.
const int LG_MAX_SHADOW_VIEWS = 96;
layout(std140, binding = 15) uniform ShadowViews { ShadowView views[LG_MAX_SHADOW_VIEWS]; };

// The view of a light (first view `first`, `count` 1 or 6) that sees direction `d` from it:
// for a cube the face of d's major axis, in the order +X, -X, +Y, -Y, +Z, -Z.
ShadowView view_toward(float first, float count, vec3 d) {
  vec3 a = abs(d);
  int face = a.x >= a.y && a.x >= a.z ? (d.x > 0.0 ? 0 : 1) : a.y >= a.z ? (d.y > 0.0 ? 2 : 3) : (d.z > 0.0 ? 4 : 5);
  return views[int(first) + (count > 1.0 ? face : 0)];
}

// The atlas texel of a view at clip position `clip`, inside its tile.
ivec2 atlas_texel(ShadowView view, vec4 clip, ivec2 offset) {
  vec2 uv = clamp(clip.xy / clip.w * 0.5 + 0.5, 0.0, 1.0);
  ivec2 lo = ivec2(view.tile.xy), hi = lo + ivec2(view.tile.z) - 1;
  return clamp(lo + ivec2(uv * view.tile.z) + offset, lo, hi);
}

#endif
