// What the nodes that carry one bounce of the main directional light share (gi.lpv, gi.voxel):
// which light that is, and the box their grid covers.
#pragma once

#include <span>

#include "runtime/scene/mesh_tools.h"

namespace lg {

struct SceneView;

// The first directional light that casts shadows, else the first; -1 when there is none.
int main_directional_light(const SceneView& scene);

// The box around every draw this frame, from each mesh's own box (`mesh_boxes`, indexed by mesh)
// moved by its draw's transform: a few corners a draw, so it is cheap enough to follow moving
// objects every frame (the scene's version changes with its meshes, not with where they stand).
// A scene without draws gets a unit box, as scene_bounds() gives.
Bounds draws_bounds(const SceneView& scene, std::span<const Bounds> mesh_boxes);

}  // namespace lg
