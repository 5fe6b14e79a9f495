// The dispatches of gi.lpv's and gi.voxel's voxelization (lpv_voxelize.comp, voxelize.comp):
// every draw's triangles marked into a grid. The shaders share their bindings (constants 0, the
// draws 1, the mesh's vertices 2 and indices 3, the grid's sums 4), their push constants
// (VoxelizePush) and their local size: 8 triangles x 8 slabs of cell layers, a slab as many
// layers as keep an invocation's loop under lavapipe's 65,535 iterations. A dispatch holds at
// most Vulkan's least maxComputeWorkGroupCount of groups along the triangles; a larger mesh
// takes several.
#pragma once

#include <string_view>

#include "nodes/gi/common/cell_grid.h"
#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/host_buffer.h"

namespace lg {

void voxelize_draws(PassContext& ctx, std::string_view shader, const CellGrid& grid, const HostBuffer& constants,
                    const HostBuffer& draws, const Buffer& sums);

}  // namespace lg
