// The probes of gi.irradiance_volume as its lookup reads them (shaders/probe_volume.glsl), built
// from baked ProbeGrids on the CPU by pack_probe_atlas(); probe_atlas_images.h puts them on the
// device. Probes are numbered across the volumes in order (each volume's after the previous
// one's, numbered as in ProbeGrid); probe p owns tile (p % tiles_per_row, p / tiles_per_row) of
// three images laid out alike, so that one hardware bilinear fetch replaces four loads and the
// octahedral wrap logic per map:
// - irradiance (rgba16f): 8 x 8 texels a tile, the 6 x 6 octahedral map inside a one-texel
//   border that repeats the texels octahedral_wrap() names (DDGI's border), so bilinear
//   filtering with clamped, linear sampling reads exactly the taps octahedral_taps() does;
// - distance (rg32f): 16 x 16 texels a tile, the 14 x 14 distance moments bordered the same way.
//   32-bit, not 16: the Chebyshev test takes variance = E[d^2] - E[d]^2, and half floats' 11 bits
//   would leave an error of ~1e-3 d^2 in it, as large as the variance near a wall;
// - records (rgba32f, read texel by texel): 16 texels a tile in one row: the probe's position
//   (w: 1 on, 0 off), its 9 SH coefficients (rgb) and its 6 ambient-cube faces (rgb).
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "nodes/gi/probes/probe_grid.h"

namespace lg {

struct GpuProbeVolume {  // shaders/probe_volume.glsl ProbeVolume (std430)
  glm::mat4 world_from_grid{1.0f};
  glm::mat4 grid_from_world{1.0f};
  glm::ivec4 counts{1};  // w: the volume's first probe
  glm::vec4 cell{1.0f};  // x: ProbeGrid::min_spacing()
};
static_assert(sizeof(GpuProbeVolume) == 160);

inline constexpr size_t kMaxProbeVolumes = 64;                      // shaders/probe_volume.glsl LG_MAX_PROBE_VOLUMES
inline constexpr int kIrradianceTile = kProbeIrradianceTexels + 2;  // with the border
inline constexpr int kDistanceTile = kProbeDistanceTexels + 2;
inline constexpr int kProbeRecordTexels = 1 + kProbeShCount + 6;  // position, SH, ambient cube
static_assert(kProbeRecordTexels == 16);                          // shaders/probe_volume.glsl

// One image of the atlas: float RGBA (4 floats a texel, row by row), converted to the image's
// format on upload.
struct AtlasImage {
  uint32_t width = 1, height = 1;
  std::vector<float> rgba = std::vector<float>(4, 0.0f);
};

struct ProbeAtlas {
  std::vector<GpuProbeVolume> volumes;  // at most kMaxProbeVolumes
  uint32_t probe_count = 0;
  uint32_t tiles_per_row = 1, tile_rows = 1;
  AtlasImage irradiance, distance, records;
};

// Lays out every probe of `grids`; tiles fill rows of the power of two of tiles at or above
// sqrt(probes), so the images stay about square and the shader finds a tile with shifts. Throws
// std::invalid_argument when a side would exceed `max_image_side` texels (the device's
// maxImageDimension2D) or there are more than kMaxProbeVolumes volumes.
ProbeAtlas pack_probe_atlas(std::span<const ProbeGrid> grids, uint32_t max_image_side);

}  // namespace lg
