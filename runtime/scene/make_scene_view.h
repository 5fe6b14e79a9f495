// Flattens an ECS world into the SceneView one frame's passes read: world-space draws and
// lights, the camera's matrices (projection.h) and the world's assets.
#pragma once

#include "runtime/scene/scene_view.h"
#include "runtime/scene/world.h"

namespace lg {

// The camera is world.active_camera, else the Camera entity with the lowest index, else a
// default camera at the origin looking down -Z. The environment and the exposure come from the
// lowest-index EnvironmentLight and PostProcessSettings. With `previous` (last frame's view),
// each draw's previous_world is the matching entity's world matrix then and
// previous_view_projection the camera's then; otherwise they equal the current ones.
// version is world.asset_revision(); meshes and textures are the world's own, shared
// (scene_view.h). Throws std::invalid_argument for an aspect ratio that is not positive or a
// parent chain that loops.
SceneView make_scene_view(const World& world, float aspect_ratio, const SceneView* previous = nullptr);

}  // namespace lg
