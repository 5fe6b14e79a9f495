// gi.reflection_capture's raster capture (docs/reflection-probes.md): faces of the probes' cubes
// drawn on the GPU with the frame's own shading. Each face is a 90-degree camera at the probe
// (cube_face_camera.h) over the environment (shaders/capture_sky.frag), then every opaque and
// alpha-tested mesh of the scene lit per fragment by forward_shading.glsl: the material as the
// G-buffer samples it, lighting.deferred's lights (no shadow maps) and lighting.ibl's
// environment. Blended meshes are left out (scene.forward_transparent sorts them for one camera).
// The lights themselves are not drawn, as the path-traced capture leaves them out.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "nodes/lighting/deferred/light_buffers.h"
#include "nodes/scene/forward_transparent/forward_bindings.h"
#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"

namespace lg {

struct CubeFace {
  uint32_t probe;  // index into SceneView::reflection_probes and the cubes
  int face;        // cube_map.h's order
};

class RasterCubeCapture {
 public:
  RasterCubeCapture(Context& gpu, const std::string& name);

  // Records `faces` into mip 0 of `cubes` (one cube per probe of the scene, colour-renderable,
  // in READ_ONLY_OPTIMAL before and after). `specular`, where not empty, replaces
  // `resources.specular` per probe (a second bounce reads the probes' own first capture).
  void record(PassContext& ctx, std::span<const CubeFace> faces, std::span<Image> cubes,
              const ForwardResources& resources, const ForwardSettings& settings,
              std::span<const VkImageView> specular = {});

 private:
  const Pipeline& sky_pipeline(PassContext& ctx, VkFormat color);
  const Pipeline& mesh_pipeline(PassContext& ctx, VkFormat color, bool masked, bool double_sided);
  void prepare_depth(PassContext& ctx, uint32_t size);

  std::string name_;
  LightBuffers lights_;
  HostBuffer draws_, settings_, cameras_;
  std::optional<Image> depth_;
};

}  // namespace lg
