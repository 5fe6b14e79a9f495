// What gi.irradiance_volume's in-graph bake depends on, as one number: the scene's assets
// (SceneView::version: meshes, materials, textures), every light's fields, the environment and
// the volumes themselves. The camera, the exposure and the draws' previous transforms are left
// out, so a moving camera keeps the bake.
#pragma once

#include <cstdint>

#include "runtime/scene/scene_view.h"

namespace lg {

uint64_t probe_bake_key(const SceneView& scene);

// The volumes alone (their frames, sizes and probe counts): the dynamic mode bakes afresh when
// they change, and otherwise updates the probes it has.
uint64_t probe_volume_key(const SceneView& scene);

// What gi.reflection_capture's cubes depend on: the same assets, lights and environment as
// probe_bake_key(), and the reflection probes instead of the volumes.
uint64_t reflection_capture_key(const SceneView& scene);

}  // namespace lg
