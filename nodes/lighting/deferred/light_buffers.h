// The lights as lighting.deferred's shaders read them (shaders/lights.glsl, direct_lights.glsl,
// area_lights.glsl): the constants block and one uniform block per kind of light, filled from
// the scene. scene.forward_transparent lights its surfaces from the same buffers.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "nodes/lighting/deferred/local_shadows.h"
#include "nodes/lighting/deferred/ltc_table.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/scene/scene_view.h"

namespace lg {

// Lights of each kind a frame shades at most (lights.glsl's LG_MAX_LIGHTS); more (after culling
// to the view where the node culls: lighting.deferred and scene.forward_transparent; reflection
// captures see every light) is an error naming the kind (write_lights throws).
inline constexpr size_t kMaxLightsPerKind = 256;
// Local shadow views a frame draws at most (local_shadow_atlas.glsl's LG_MAX_SHADOW_VIEWS): six
// for each of the 16 lights the schema's shadow_budget allows; a uniform block too (80 bytes each).
inline constexpr size_t kMaxShadowViews = 96;

// A spot's cone as glTF's falloff wants it: x, y of the ramp cos(angle) x + y, 0 at the outer
// cone and 1 at the inner; an inner cone as wide as the outer one is kept 0.001 apart in cosine
// (the spec's guard), a hard but finite edge. gi.voxel's injected spots take the same ramp.
glm::vec2 spot_ramp(const SpotLightData& light);

// shaders/lights.glsl's Constants (std140).
struct LightConstants {
  CameraConstants camera;
  glm::mat4 shadow_from_world;
  glm::vec4 shadow;  // 1 / map size, map drawn, normal offset, depth bias
  uint32_t counts[4];
  uint32_t counts2[4];
  glm::vec4 local_shadow;  // 1 when the atlas was drawn, its views' near plane, area-light shadow samples
  // The BRDF's albedo table, for the lobes' energy sharing (brdf_albedo.glsl): constant, but every
  // pass that shades with brdf.glsl binds this block already.
  std::array<glm::vec4, kBrdfAlbedoSize* kBrdfAlbedoSize / 2> brdf_albedo = brdf_albedo_texels();
};

// The first directional light that casts shadows owns the shadow map, or -1.
int shadow_caster(const SceneView& scene);

class LightBuffers {
 public:
  LightBuffers(Context& gpu, const std::string& id);

  // Writes every light list: `caster` (shadow_caster()) marked as using the shadow map, the
  // point and spot lights with their views of `local`; sets the counts in `constants`. Throws
  // std::runtime_error when a kind has more than kMaxLightsPerKind lights.
  void write_lights(const SceneView& scene, int caster, const LocalShadows& local, LightConstants& constants);

  // The constants at binding 0 and the lists at the bindings direct_lights.glsl,
  // local_shadow_atlas.glsl and area_lights.glsl declare, the LTC table with the area lists
  // (the shadow map and atlas images are the caller's: 10 and 14).
  void add_constants(std::vector<DescriptorWrite>& writes) const;
  void add_direct_lists(std::vector<DescriptorWrite>& writes) const;
  void add_shadow_views(std::vector<DescriptorWrite>& writes) const;
  void add_area_lists(std::vector<DescriptorWrite>& writes) const;

  HostBuffer constants;

 private:
  HostBuffer directional_, points_, spots_, spheres_, tubes_, rects_, shadow_views_;
  HostBuffer ltc_;  // ltc_table_texels(), written once
};

}  // namespace lg
