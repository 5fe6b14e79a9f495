// Reads a .lgbake file (docs/bake-format.md) made by `lumagraph bake --mode vertex|texel` for
// meshes drawn with given transforms (one scene-file entity's, in their own space; or every draw
// of a scene file), checking that it was baked from exactly this geometry: a whole bake (not one
// chunk), per vertex or per texel, whose input has the same parts, vertex and triangle counts
// and hash (input_hash) as these meshes where they stand. Bent normals come back in each mesh's
// own space.
// Volume bakes are refused: they belong to the scene, not to a mesh (occlusion.bake bakes one).
// Pass it to the scene loader as WorldLoadOptions::read_occlusion (runtime/scene/load_world.h).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "runtime/scene/mesh_occlusion.h"
#include "runtime/scene/scene_view.h"

namespace lg {

// An OcclusionBakeReader: one MeshOcclusion per mesh, or std::runtime_error naming the bake file
// and saying what differs.
std::vector<std::shared_ptr<const MeshOcclusion>> read_occlusion_bake(const std::string& bake_path,
                                                                      std::span<const MeshData* const> meshes,
                                                                      std::span<const glm::mat4> transforms);

}  // namespace lg
