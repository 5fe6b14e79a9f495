// The probes of gi.irradiance_volume as the device reads them: the C++ side of the std430 layout
// in shaders/probe_volume.glsl (ProbeVolume, Probe), filled from baked ProbeGrids. Volumes keep
// their order; each volume's probes follow the previous volume's, numbered as in ProbeGrid.
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "nodes/gi/probes/probe_grid.h"

namespace lg {

struct GpuProbeVolume {  // shaders/probe_volume.glsl ProbeVolume
  glm::mat4 world_from_grid{1.0f};
  glm::mat4 grid_from_world{1.0f};
  glm::ivec4 counts{1};  // w: the volume's first probe
  glm::vec4 cell{1.0f};  // x: ProbeGrid::min_spacing()
};
static_assert(sizeof(GpuProbeVolume) == 160);

struct GpuProbe {            // shaders/probe_volume.glsl Probe
  glm::vec4 position{0.0f};  // w: 1 active
  glm::vec4 sh[kProbeShCount];
  glm::vec4 ambient_cube[6];
  glm::vec4 irradiance[kProbeIrradianceTexels * kProbeIrradianceTexels];
  glm::vec2 distance[kProbeDistanceTexels * kProbeDistanceTexels];
};
// std430: vec4 members, a vec2 array of stride 8, the struct a multiple of 16.
static_assert(sizeof(GpuProbe) == 16 * (1 + kProbeShCount + 6 + 36) + 8 * 196);
static_assert(sizeof(GpuProbe) % 16 == 0);
static_assert(offsetof(GpuProbe, distance) == 16 * (1 + kProbeShCount + 6 + 36));

struct ProbeBuffers {
  std::vector<GpuProbeVolume> volumes;
  std::vector<GpuProbe> probes;
};

ProbeBuffers pack_probes(std::span<const ProbeGrid> grids);

}  // namespace lg
