// The raster captures (docs/reflection-probes.md, docs/planar-reflections.md): the scene drawn on
// the GPU with the frame's own shading from cameras other than the frame's, into
// gi.reflection_capture's cube faces (a 90-degree camera at the probe, cube_face_camera.h) and
// gi.planar_reflection's mirrored views. Each view is the environment
// (shaders/capture_sky.frag), then every opaque and alpha-tested mesh of the scene lit per
// fragment by forward_shading.glsl: the material as the G-buffer samples it,
// lighting.deferred's lights (no shadow maps) and lighting.ibl's environment. Blended meshes are
// left out (scene.forward_transparent sorts them for one camera), and so are the entities marked
// `captured_by_probes: false` in cube faces. With gi.irradiance_volume's probes linked, the
// diffuse light is the environment's mixed toward the volume's by its coverage, as lighting.ibl
// mixes it in the frame (capture_surface.glsl). The lights themselves are not drawn, as the
// path-traced capture leaves them out. Both kinds of view are mirror images of a right-handed
// camera's: front faces wind clockwise in them.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "nodes/common/camera_constants.h"
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

// One view to draw: its camera, and a colour-renderable 2D view of the target (in
// ATTACHMENT_OPTIMAL) of `width` x `height`, which it covers whole.
struct CaptureView {
  CameraConstants camera;
  VkImageView target;
  uint32_t width, height;
  VkImageView specular = VK_NULL_HANDLE;         // the surfaces' specular map; null: the resources'
  glm::vec4 clip_plane{0.0f, 0.0f, 0.0f, 1.0f};  // ForwardSettings::clip_plane of this view
};

// gi.irradiance_volume's probes as the capture's shading reads them (capture_surface.glsl, bindings
// 23 to 26), where the node's `probe_volume` input is linked; otherwise placeholders that the
// specialization constant `linked` skips.
struct CaptureVolume {
  bool linked = false;
  uint32_t representation = 3;  // ProbeRepresentation
  bool visibility = true;
  VkBuffer volumes = VK_NULL_HANDLE;  // the input's block
  VkImageView records = VK_NULL_HANDLE, irradiance = VK_NULL_HANDLE, distance = VK_NULL_HANDLE;
};

struct CaptureResources {
  ForwardResources forward;
  CaptureVolume volume;
};

// What a raster capture's shading binds: the node's inputs `sh`, `irradiance`, `specular` and
// `brdf_lut` where the scene has an environment light, and the probes of `probe_volume` where
// linked (its irradiance mixed into the diffuse light as lighting.ibl mixes the volume's:
// forward_shading.glsl), otherwise placeholders that the settings' flags skip.
class CaptureInputs {
 public:
  // Throws, naming the node, where the scene has an environment light and they are not linked
  // (the schemas' `requires` rules refuse such graphs first), or where `probe_volume` is linked
  // without `brdf_lut` or from a node that lends no probes.
  CaptureResources bind(PassContext& ctx, float intensity, ForwardSettings& settings);

  // The linked volume's upload version (probe_volume_source.h), 0 without one: a cached capture
  // is stale when it changes.
  static uint64_t volume_version(PassContext& ctx);

 private:
  std::optional<HostBuffer> sh_placeholder_, volumes_placeholder_;
  std::optional<Image> cube_placeholder_;
};

class RasterCapture {
 public:
  RasterCapture(Context& gpu, const std::string& name);

  // Records `faces` into mip 0 of `cubes` (one cube per probe of the scene, colour-renderable,
  // in READ_ONLY_OPTIMAL before and after). `specular`, where not empty, replaces
  // `resources.specular` per probe (a second bounce reads the probes' own first capture).
  void record(PassContext& ctx, std::span<const CubeFace> faces, std::span<Image> cubes,
              const CaptureResources& resources, const ForwardSettings& settings,
              std::span<const VkImageView> specular = {});

  // Records `views` of `format` with `settings` (each view's own clip plane); every mesh drawn
  // unless `probes_only` leaves out those the probes do not see. The caller puts the targets in
  // ATTACHMENT_OPTIMAL and takes them back.
  void record_views(PassContext& ctx, std::span<const CaptureView> views, VkFormat format,
                    const CaptureResources& resources, const ForwardSettings& settings, bool probes_only);

 private:
  const Pipeline& sky_pipeline(PassContext& ctx, VkFormat color);
  const Pipeline& mesh_pipeline(PassContext& ctx, VkFormat color, bool masked, bool double_sided,
                                const CaptureVolume& volume);
  void prepare_depth(PassContext& ctx, uint32_t width, uint32_t height);

  std::string name_;
  LightBuffers lights_;
  HostBuffer draws_, settings_, cameras_;
  std::optional<Image> depth_;
};

}  // namespace lg
