#pragma once
// gi.voxel's local lights (shaders/voxel_local_lights.comp): the scene's point, spot, sphere, tube
// and rectangle lights, each as a point at its centre with an intensity toward the voxels.
#include <array>
#include <glm/vec4.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

struct VoxelLocalLight {  // std140, shaders/voxel_local_lights.comp's LocalLight
  glm::vec4 position_range{0.0f};  // xyz: the centre; w: the range (0: none)
  glm::vec4 intensity_size{0.0f};  // rgb: W/sr toward the axis; w: the area light's area / pi, m^2
  glm::vec4 axis_kind{0.0f};       // xyz: the axis (the way the light travels); w: the kind (below)
  glm::vec4 spot{0.0f};            // x, y: a spot's ramp, t = clamp(cos x + y, 0, 1)
};

// voxel_local_lights.comp's kinds of intensity toward direction w.
enum class VoxelLightKind { every_way = 0, spot = 1, one_sided = 2, two_sided = 3 };

constexpr int kMaxVoxelLocalLights = 16;  // voxel_local_lights.comp's kMaxLocalLights

struct VoxelLocalLights {
  std::array<VoxelLocalLight, kMaxVoxelLocalLights> lights{};
  int count = 0;  // the first `count` of `lights`; the scene's lights past the first 16 are left out
};

// The scene's local lights in voxel_local_lights.comp's form, in the order point, spot, sphere,
// tube, rectangle.
VoxelLocalLights voxel_local_lights(const SceneView& scene);

}  // namespace lg
