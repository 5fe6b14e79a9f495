// Which point, spot, sphere, tube and rectangle lights get shadow maps in a frame, and where:
// the shadow budget goes to the shadow-casting lights nearest the camera, each gets square tiles
// of one depth atlas (a spot one perspective view down its cone; a point light, a spot wider
// than 60 degrees and every area light six views along the axes, a cube map about its centre),
// and each view's matrix into its tile. Lights past the budget light without shadows. Plain
// data: the deferred kernel draws the views, the direct pass (shaders/direct_lights.glsl) and
// the area pass (shaders/area_shadows.glsl) read them back.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

// Depth is stored as near / distance along the view (reversed Z, infinite far plane), so a
// surface closer to a light than this is not in its map.
constexpr float local_shadow_near = 0.02f;

// Each view's field of view covers its cone or cube face with this many texels to spare on
// every side, so that the 3x3 filter and the normal offset stay inside the tile.
constexpr uint32_t local_shadow_margin = 4;

struct LocalShadowView {
  glm::mat4 clip_from_world{1.0f};  // Vulkan clip space, reversed Z, clip.w the distance along the view
  glm::uvec2 origin{0};             // the tile's corner in the atlas, texels
  uint32_t size = 0;                // the tile's edge, texels
  float texel_per_distance = 0.0f;  // world size of one texel at distance 1 along the view
};

struct LocalShadows {
  std::vector<LocalShadowView> views;
  // Per light of the SceneView's lists: its first view, or -1 for none; a light has one view
  // or six (cube faces +X, -X, +Y, -Y, +Z, -Z, the order shaders/local_shadow_atlas.glsl picks
  // them in). Only a spot may have one; every area light with a map has six.
  std::vector<int> point_first_view, spot_first_view, spot_view_count;
  std::vector<int> sphere_first_view, tube_first_view, rect_first_view;
};

// No light with a view (what a pass without the atlas lights with).
LocalShadows no_local_shadows(const SceneView& scene);

// The atlas is a grid of ceil(sqrt(6 budget))^2 tiles, room for `budget` point lights.
uint32_t local_shadow_tile_size(uint32_t atlas_size, uint32_t budget);

LocalShadows plan_local_shadows(const SceneView& scene, uint32_t budget, uint32_t atlas_size);

}  // namespace lg
