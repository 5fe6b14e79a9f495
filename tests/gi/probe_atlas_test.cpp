// gi.irradiance_volume's probe atlas (nodes/gi/irradiance_volume/probe_atlas.h) on the CPU: every
// border texel repeats the map texel octahedral_wrap() names, so that a bilinear fetch from a
// bordered tile (clamped, as the GPU's linear sampler reads it) gives what octahedral_taps() does
// from the map itself; records and volumes say where each probe is.
#include "nodes/gi/irradiance_volume/probe_atlas.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "nodes/gi/probes/octahedral_map.h"

namespace lg::test {
namespace {

// Two volumes (3 x 2 x 2 and 1 x 1 x 3 probes) whose map texels all differ, from fresh random
// values: a texel read from the wrong place cannot match by chance.
std::vector<ProbeGrid> random_grids(std::mt19937& rng) {
  std::uniform_real_distribution<float> value(0.1f, 10.0f);
  std::vector<ProbeGrid> grids;
  for (glm::ivec3 counts : {glm::ivec3(3, 2, 2), glm::ivec3(1, 1, 3)}) {
    IrradianceVolumeData v;
    v.probe_counts = counts;
    v.size = glm::vec3(2.0f, 1.0f, 3.0f);
    ProbeGrid& g = grids.emplace_back(v);
    for (ProbeData& p : g.probes) {
      p.active = value(rng) > 3.0f;
      p.offset = glm::vec3(value(rng), value(rng), value(rng)) * 0.01f;
      for (glm::vec3& t : p.irradiance) t = {value(rng), value(rng), value(rng)};
      for (glm::vec2& t : p.distance) t = {value(rng), value(rng)};
      for (glm::vec3& c : p.sh) c = {value(rng), value(rng), value(rng)};
      for (glm::vec3& c : p.ambient_cube) c = {value(rng), value(rng), value(rng)};
    }
  }
  return grids;
}

glm::vec4 atlas_texel(const AtlasImage& image, int x, int y) {
  x = std::clamp(x, 0, int(image.width) - 1), y = std::clamp(y, 0, int(image.height) - 1);  // clamp to edge
  const float* t = &image.rgba[4 * (size_t(y) * image.width + size_t(x))];
  return {t[0], t[1], t[2], t[3]};
}

// What a GPU's bilinear fetch at texel coordinates `at` returns (texel centres at i + 0.5).
glm::dvec4 bilinear(const AtlasImage& image, glm::dvec2 at) {
  const glm::dvec2 p = at - 0.5, f = glm::floor(p), t = p - f;
  glm::dvec4 sum(0.0);
  for (int n = 0; n < 4; ++n) {
    const int dx = n & 1, dy = n >> 1;
    sum +=
        (dx ? t.x : 1.0 - t.x) * (dy ? t.y : 1.0 - t.y) * glm::dvec4(atlas_texel(image, int(f.x) + dx, int(f.y) + dy));
  }
  return sum;
}

// As probe_volume.glsl's sample_octahedral(): map texel (i, j) at tile texel (i + 1, j + 1).
template <size_t N, class T>
void expect_bordered_map_matches(const AtlasImage& image, glm::uvec2 tile, const std::array<T, N>& map, int k,
                                 std::mt19937& rng) {
  for (int j = -1; j <= k; ++j)
    for (int i = -1; i <= k; ++i) {
      const glm::ivec2 s = octahedral_wrap(i, j, k);
      const glm::vec4 border = atlas_texel(image, int(tile.x) * (k + 2) + i + 1, int(tile.y) * (k + 2) + j + 1);
      for (int c = 0; c < T::length(); ++c) ASSERT_EQ(border[c], map[size_t(s.y) * k + s.x][c]) << i << ", " << j;
    }
  // Random directions, and the poles and the equator's corners, where the wrap is hardest.
  std::normal_distribution<double> normal;
  std::vector<glm::dvec3> directions = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {1e-9, 1e-9, -1}};
  for (int n = 0; n < 2000; ++n)
    directions.push_back(glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng))));
  for (const glm::dvec3& d : directions) {
    const OctahedralTaps taps = octahedral_taps(d, k);
    glm::dvec4 expected(0.0);
    for (int n = 0; n < 4; ++n) {
      const T& texel = map[size_t(taps.texel[n].y) * k + taps.texel[n].x];
      for (int c = 0; c < T::length(); ++c) expected[c] += taps.weight[n] * texel[c];
    }
    const glm::dvec2 at = glm::dvec2(glm::ivec2(tile) * (k + 2) + 1) + octahedral_encode(d) * double(k);
    const glm::dvec4 fetched = bilinear(image, at);
    // Both are the same four products in double: only summation order differs.
    for (int c = 0; c < T::length(); ++c) ASSERT_NEAR(fetched[c], expected[c], 1e-12 * std::abs(expected[c])) << d.x;
  }
}

TEST(ProbeAtlas, BordersRepeatTheirSourceTexelsAndBilinearFetchesMatchTheTaps) {
  std::mt19937 rng(16);
  const std::vector<ProbeGrid> grids = random_grids(rng);
  const ProbeAtlas atlas = pack_probe_atlas(grids, 16384);
  ASSERT_EQ(atlas.probe_count, 15u);
  EXPECT_EQ(atlas.tiles_per_row, 4u);  // ceil(sqrt(15))
  EXPECT_EQ(atlas.tile_rows, 4u);
  EXPECT_EQ(atlas.irradiance.width, 4u * 8u);
  EXPECT_EQ(atlas.distance.height, 4u * 16u);
  uint32_t p = 0;
  for (size_t v = 0; v < grids.size(); ++v) {
    EXPECT_EQ(atlas.volumes[v].counts.w, int(p));
    for (size_t i = 0; i < grids[v].probes.size(); ++i, ++p) {
      const ProbeData& d = grids[v].probes[i];
      const glm::uvec2 tile(p % atlas.tiles_per_row, p / atlas.tiles_per_row);
      expect_bordered_map_matches(atlas.irradiance, tile, d.irradiance, kProbeIrradianceTexels, rng);
      expect_bordered_map_matches(atlas.distance, tile, d.distance, kProbeDistanceTexels, rng);
      const int x = int(tile.x) * kProbeRecordTexels, y = int(tile.y);
      const glm::vec4 position = atlas_texel(atlas.records, x, y);
      EXPECT_EQ(glm::vec3(position), glm::vec3(grids[v].grid_position(i) + glm::dvec3(d.offset)));
      EXPECT_EQ(position.w, d.active ? 1.0f : 0.0f);
      EXPECT_EQ(glm::vec3(atlas_texel(atlas.records, x + 1 + 4, y)), d.sh[4]);
      EXPECT_EQ(glm::vec3(atlas_texel(atlas.records, x + 1 + kProbeShCount + 5, y)), d.ambient_cube[5]);
    }
  }
}

// An atlas too large for the device is refused with the numbers, not cut short.
TEST(ProbeAtlas, TooManyProbesForTheDeviceAreRefused) {
  std::mt19937 rng(1);
  const std::vector<ProbeGrid> grids = random_grids(rng);
  EXPECT_THROW(pack_probe_atlas(grids, 48), std::invalid_argument);  // 3 tiles a row, 5 rows of 16 texels
  EXPECT_NO_THROW(pack_probe_atlas(grids, 80));
}

}  // namespace
}  // namespace lg::test
