#include "nodes/gi/common/voxelize_draws.h"

#include <algorithm>
#include <cstdint>
#include <span>

#include "nodes/common/compute.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/exec/gpu_scene.h"

namespace lg {
namespace {

constexpr uint32_t kVoxelizeTile = 8;  // the shaders' local size: triangles x slabs
constexpr uint32_t kTrianglesPerDispatch = 65535 * kVoxelizeTile;
constexpr int kLoopIterations = 65535;

struct VoxelizePush {  // both shaders'
  uint32_t draw_index, first_triangle, triangle_count, slab_layers;
};

}  // namespace

void voxelize_draws(PassContext& ctx, std::string_view shader, const CellGrid& grid, const HostBuffer& constants,
                    const HostBuffer& draws, const Buffer& sums) {
  const SceneView& scene = ctx.scene();
  const int slab_layers = std::max(1, kLoopIterations / (grid.counts.x * grid.counts.y));
  const int slabs = (grid.counts.z + slab_layers - 1) / slab_layers;
  for (uint32_t i = 0; i < scene.draws.size(); ++i) {
    const GpuMesh& mesh = ctx.gpu_scene().mesh(scene.draws[i].mesh);
    const uint32_t triangles = mesh.index_count / 3;
    const DescriptorWrite writes[] = {uniform_buffer(0, constants.handle()), storage_buffer(1, draws.handle()),
                                      storage_buffer(2, mesh.vertices.handle()),
                                      storage_buffer(3, mesh.indices.handle()), storage_buffer(4, sums.handle())};
    for (uint32_t first = 0; first < triangles; first += kTrianglesPerDispatch) {
      const VoxelizePush push{i, first, std::min(triangles - first, kTrianglesPerDispatch), uint32_t(slab_layers)};
      dispatch_compute(ctx, shader, writes, push.triangle_count, uint32_t(slabs), std::as_bytes(std::span(&push, 1)),
                       kVoxelizeTile);
    }
  }
}

}  // namespace lg
