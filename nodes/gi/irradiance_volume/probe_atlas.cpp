#include "nodes/gi/irradiance_volume/probe_atlas.h"

#include <cmath>
#include <glm/matrix.hpp>
#include <stdexcept>
#include <string>

#include "nodes/gi/probes/octahedral_map.h"

namespace lg {
namespace {

AtlasImage blank_image(uint32_t width, uint32_t height) {
  return {width, height, std::vector<float>(size_t(width) * height * 4, 0.0f)};
}

float* texel(AtlasImage& image, uint32_t x, uint32_t y) {
  return &image.rgba[4 * (size_t(y) * image.width + x)];
}

// Tile (tx, ty) of `image`, `k` x `k` texels of `map` inside a one-texel border: border texel
// (i, j) of the map (i or j at -1 or k) repeats octahedral_wrap(i, j, k).
template <class T>
void write_bordered_map(AtlasImage& image, uint32_t tx, uint32_t ty, const T& map, int k) {
  for (int j = -1; j <= k; ++j)
    for (int i = -1; i <= k; ++i) {
      const glm::ivec2 source = octahedral_wrap(i, j, k);
      const auto& value = map[size_t(source.y) * k + source.x];
      float* out = texel(image, tx * (k + 2) + uint32_t(i + 1), ty * (k + 2) + uint32_t(j + 1));
      for (int c = 0; c < value.length(); ++c) out[c] = value[c];
    }
}

GpuProbeVolume volume_of(const ProbeGrid& grid, uint32_t first_probe) {
  GpuProbeVolume v;
  // The grid's own matrices are private; these are the same from its public axes.
  glm::dmat4 world_from_grid(1.0);
  for (int a = 0; a < 3; ++a) world_from_grid[a] = glm::dvec4(grid.axis(a), 0.0);
  world_from_grid[3] = glm::dvec4(grid.grid_position(0), 1.0);
  v.world_from_grid = glm::mat4(world_from_grid);
  v.grid_from_world = glm::mat4(glm::inverse(world_from_grid));
  v.counts = glm::ivec4(grid.counts(), int(first_probe));
  v.cell = glm::vec4(float(grid.min_spacing()), 0.0f, 0.0f, 0.0f);
  return v;
}

}  // namespace

ProbeAtlas pack_probe_atlas(std::span<const ProbeGrid> grids, uint32_t max_image_side) {
  ProbeAtlas atlas;
  size_t probes = 0;
  for (const ProbeGrid& grid : grids) probes += grid.probes.size();
  if (grids.size() > kMaxProbeVolumes)
    throw std::invalid_argument("the scene has " + std::to_string(grids.size()) +
                                " irradiance volumes, more than the lookup takes (" + std::to_string(kMaxProbeVolumes) +
                                ")");
  const uint32_t widest = uint32_t(kDistanceTile);  // distance and record tiles are 16 texels wide
  const size_t square = size_t(std::ceil(std::sqrt(double(probes))));
  size_t per_row = 1;
  while (per_row < square && 2 * per_row * widest <= max_image_side) per_row *= 2;
  atlas.tiles_per_row = uint32_t(per_row * widest <= max_image_side ? per_row : 0);
  const size_t rows =
      atlas.tiles_per_row ? std::max<size_t>(1, (probes + atlas.tiles_per_row - 1) / atlas.tiles_per_row) : probes;
  if (rows * widest > max_image_side)
    throw std::invalid_argument("the scene's " + std::to_string(probes) + " probes need an atlas of " +
                                std::to_string(rows * widest) + " texels a side, more than the device's " +
                                std::to_string(max_image_side) + ": use fewer probes");
  atlas.tile_rows = uint32_t(rows);
  atlas.probe_count = uint32_t(probes);
  atlas.irradiance = blank_image(atlas.tiles_per_row * kIrradianceTile, atlas.tile_rows * kIrradianceTile);
  atlas.distance = blank_image(atlas.tiles_per_row * kDistanceTile, atlas.tile_rows * kDistanceTile);
  atlas.records = blank_image(atlas.tiles_per_row * kProbeRecordTexels, atlas.tile_rows);
  uint32_t p = 0;
  for (const ProbeGrid& grid : grids) {
    atlas.volumes.push_back(volume_of(grid, p));
    for (size_t i = 0; i < grid.probes.size(); ++i, ++p) {
      const ProbeData& d = grid.probes[i];
      const uint32_t tx = p % atlas.tiles_per_row, ty = p / atlas.tiles_per_row;
      write_bordered_map(atlas.irradiance, tx, ty, d.irradiance, kProbeIrradianceTexels);
      write_bordered_map(atlas.distance, tx, ty, d.distance, kProbeDistanceTexels);
      float* record = texel(atlas.records, tx * kProbeRecordTexels, ty);
      const glm::vec3 position(grid.grid_position(i) + glm::dvec3(d.offset));
      for (int c = 0; c < 3; ++c) record[c] = position[c];
      record[3] = d.active ? 1.0f : 0.0f;
      for (int s = 0; s < kProbeShCount; ++s)
        for (int c = 0; c < 3; ++c) record[4 * (1 + s) + c] = d.sh[size_t(s)][c];
      for (int f = 0; f < 6; ++f)
        for (int c = 0; c < 3; ++c) record[4 * (1 + kProbeShCount + f) + c] = d.ambient_cube[size_t(f)][c];
    }
  }
  return atlas;
}

}  // namespace lg
