// occlusion.bake's kernel: the visibility grid baked on the CPU whenever the geometry changes, uploaded
// as a storage buffer, and looked up per pixel by one compute pass.
#include "nodes/occlusion/bake/bake_kernel.h"

#include <limits>
#include <optional>
#include <stdexcept>

#include "graph/fnv1a.h"
#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/occlusion/bake/volume_lookup.h"
#include "nodes/raytrace/ray_scene.h"
#include "nodes/raytrace/world_mesh.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

struct Constants {  // nodes/occlusion/bake/shaders/volume_lookup.comp
  CameraConstants camera;
  glm::vec4 grid_origin;
  glm::vec4 grid_spacing;
  uint32_t grid_dims[4];
};

OcclusionSettings occlusion_settings(const PlanNode& node) {
  OcclusionSettings s;
  s.rays = int(param_number(node, "rays"));
  const double distance = param_number(node, "max_distance");
  s.max_distance = distance > 0.0 ? float(distance) : std::numeric_limits<float>::infinity();
  s.falloff = param_string(node, "falloff") == "obscurance" ? OcclusionFalloff::obscurance : OcclusionFalloff::none;
  return s;
}

// What the bake depends on in a frame's view: the asset version (mesh contents) and every draw's
// mesh and transform, hashed (FNV-1a) so that moving an entity re-bakes as a new mesh does.
uint64_t geometry_key(const SceneView& scene) {
  uint64_t h = fnv1a_basis;
  auto mix = [&](const void* data, size_t size) { h = fnv1a(data, size, h); };
  mix(&scene.version, sizeof scene.version);
  for (const DrawItem& d : scene.draws) {
    mix(&d.mesh, sizeof d.mesh);
    mix(&d.world, sizeof d.world);
  }
  return h;
}

class BakeKernel final : public NodeKernel {
 public:
  explicit BakeKernel(const PlanNode& node)
      : settings_(occlusion_settings(node)),
        resolution_(uint32_t(param_number(node, "resolution"))),
        seed_(uint64_t(param_number(node, "seed"))) {
    try {
      check_occlusion_settings(settings_);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("node '" + node.id + "' (occlusion.bake): " + e.what());
    }
  }

  void record(PassContext& ctx) override {
    if (ctx.pass().pass != "lookup") throw std::logic_error("occlusion.bake has no pass '" + ctx.pass().pass + "'");
    const SceneView& scene = ctx.scene();
    if (!points_ || geometry_key(scene) != baked_key_) bake(ctx, scene);
    Image& ao = ctx.image("out.ao");
    Constants c{};
    c.camera = camera_constants(scene.camera, ao.desc().width, ao.desc().height);
    c.grid_origin = glm::vec4(glm::vec3(grid_.origin), float(volume_lookup_offset_cells * grid_.spacing.x));
    c.grid_spacing = glm::vec4(glm::vec3(grid_.spacing), 0.0f);
    for (int a = 0; a < 3; ++a) c.grid_dims[a] = grid_.dims[a];
    if (!constants_) constants_.emplace(ctx.gpu(), ctx.node().id + " constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    constants_->write_value(c);
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()),
                                      sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_buffer(3, points_->handle()),
                                      storage_image(4, ao.view()),
                                      storage_image(5, ctx.image("out.bent_normals").view())};
    dispatch_compute(ctx, "nodes/occlusion/bake/shaders/volume_lookup.comp", writes, ao.desc().width, ao.desc().height);
  }

 private:
  // The CPU bake, once per geometry (geometry_key): a scene without triangles gets an empty grid
  // (every pixel open) rather than an error, as an empty frame does in the other nodes.
  void bake(PassContext& ctx, const SceneView& scene) {
    const WorldMesh mesh = make_world_mesh(scene);
    grid_ = VisibilityGrid{};
    if (mesh.triangle_count() > 0) {
      const BakeDomain volume = BakeDomain::volume(mesh, {resolution_, 0, 0});
      grid_ = bake_visibility_grid(RayScene(mesh, scene), volume, settings_, seed_);
    }
    if (!points_) points_.emplace(ctx.gpu(), ctx.node().id + " grid", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    points_->write(grid_.points);
    baked_key_ = geometry_key(scene);
  }

  OcclusionSettings settings_;
  uint32_t resolution_;
  uint64_t seed_;
  VisibilityGrid grid_;
  uint64_t baked_key_ = 0;
  std::optional<HostBuffer> constants_, points_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_bake_kernel(const PlanNode& node) {
  return std::make_unique<BakeKernel>(node);
}

}  // namespace lg
