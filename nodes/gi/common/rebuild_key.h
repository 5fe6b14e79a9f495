// What gi.lpv and gi.voxel key their kept work on (the voxels' chain, the LPV's sky march): the
// bytes of what it was built from, compared frame to frame.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "graph/plan.h"
#include "nodes/scene/gbuffer/draw_constants.h"

namespace lg {

struct SceneView;

void append_key(std::vector<std::byte>& key, const void* data, size_t bytes);

// The geometry: the draws (transforms, materials: their constants), which mesh each draws (not
// in DrawConstants: a draw may swap meshes of the same bounds) and the meshes' contents
// (scene.version). Anything that moves changes one of those.
void append_geometry_key(std::vector<std::byte>& key, const SceneView& scene, std::span<const DrawConstants> draws);

// Whether what `access` reads is a static result of the plan (its first pass, its producer, is
// static): the same every frame. Not so for an animated sky's SH, which may change in any frame.
bool is_static_result(const Plan& plan, const PlanAccess& access);

}  // namespace lg
