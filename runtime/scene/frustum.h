// The camera's view volume as six world-space planes, and the conservative tests that leave out
// what cannot be seen: a draw whose box lies wholly outside one plane is not drawn, a light
// whose sphere of influence lies wholly outside one is not shaded. Works for any projection
// into Vulkan clip space (perspective or orthographic, reversed Z, infinite far plane): the
// planes come from the clip-from-world matrix itself. CPU only.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "runtime/scene/mesh_tools.h"
#include "runtime/scene/scene_view.h"

namespace lg {

struct Frustum {
  // (n, d) with n.p + d >= 0 inside, |n| = 1; a plane that bounds nothing (the far plane of an
  // infinite projection) is (0, 0, 0, 1): everything is inside it.
  std::array<glm::vec4, 6> planes;
};

// The volume that `clip_from_world` maps into -w <= x, y <= w, 0 <= z <= w.
Frustum view_frustum(const glm::mat4& clip_from_world);
// The scene camera's (its jittered projection * view, as camera_constants() hands the shaders).
Frustum view_frustum(const CameraView& camera);

// False only when the box lies wholly outside one plane (so near a frustum's corner a box that
// misses it may still count as touching: it is drawn, which is never wrong). An empty box
// touches nothing.
bool touches(const Frustum& frustum, const Bounds& box);
bool touches(const Frustum& frustum, glm::vec3 center, float radius);

// The box around `box` after the affine `transform` (the box of its eight corners).
Bounds transform_bounds(const Bounds& box, const glm::mat4& transform);

// Per mesh, the box around its positions in its own space (empty for a mesh without positions;
// a null slot gets an empty box too).
std::vector<Bounds> mesh_bounds(const SceneView& scene);

// The indices of the scene's draws whose world-space box touches the frustum, in draw order.
// `meshes`: mesh_bounds(scene) (kept across frames while the scene's version holds).
std::vector<uint32_t> visible_draws(const SceneView& scene, std::span<const Bounds> meshes, const Frustum& frustum);

}  // namespace lg
