// occlusion.gtao at resolution_scale 0.5 against itself at full resolution on lavapipe: the
// joint bilateral upsample (nodes/common/shaders/joint_upsample.glsl) must not carry occlusion
// across a silhouette. On the bunny world at 320x180, beside a depth edge with different
// occlusion on its two sides (the bunny's ears and back against the floor behind, its contact
// shadow against its flank) a plain bilinear upsample blends the two surfaces' occlusion (a
// halo), where the guided one keeps each surface's own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tests/occlusion/ao_render.h"

namespace lg::test {
namespace {

constexpr uint32_t kWidth = 320, kHeight = 180;
constexpr int kFrames = 8;  // both accumulated, so that the per-pixel noise is small

// How much a pixel's full-resolution occlusion differs from that of a surface across a depth
// edge within 2 pixels (the reach of a half-resolution texel's bilinear footprint): a neighbour
// more than 10% nearer or farther (reversed-Z device depth is proportional to 1 / distance, so
// its ratio is the distances'). 0 away from edges.
float contrast_across_edge(const GbufferReadback& g, const std::vector<float>& ao, uint32_t x, uint32_t y) {
  const size_t i = size_t(y) * g.width + x;
  float contrast = 0.0f;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int nx = std::clamp(int(x) + dx, 0, int(g.width) - 1), ny = std::clamp(int(y) + dy, 0, int(g.height) - 1);
      const size_t j = size_t(ny) * g.width + size_t(nx);
      if (g.depth[j] > 0.0f && std::abs(g.depth[j] - g.depth[i]) > 0.1f * std::max(g.depth[j], g.depth[i]))
        contrast = std::max(contrast, std::abs(ao[4 * j] - ao[4 * i]));
    }
  return contrast;
}

// Mean |half - full| where the occlusion across a depth edge differs by more than 0.1 (where a
// halo would show) and over every other surface pixel.
struct Difference {
  double edges = 0, elsewhere = 0;
  size_t edge_pixels = 0;
};

Difference half_against_full(const AoRender& full, const AoRender& half) {
  double sum[2] = {0, 0};
  size_t count[2] = {0, 0};
  const GbufferReadback& g = full.gbuffer;
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      const size_t i = size_t(y) * g.width + x;
      if (!(g.depth[i] > 0.0f)) continue;
      const int side = contrast_across_edge(g, full.last_ao, x, y) > 0.1f ? 0 : 1;
      sum[side] += std::abs(double(half.last_ao[4 * i]) - double(full.last_ao[4 * i]));
      ++count[side];
    }
  return {sum[0] / double(std::max<size_t>(count[0], 1)), sum[1] / double(std::max<size_t>(count[1], 1)), count[0]};
}

std::string gtao(double scale) {
  return R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "resolution_scale": )" +
         std::to_string(scale) + " } }";
}

// Measured on lavapipe: beside such edges (397 pixels) the half-resolution occlusion is 0.035
// from the full-resolution one (0.0065 elsewhere; 0.037 and 0.0055 before the depth mips started
// on the grid); a plain bilinear upsample (the same taps without the depth and normal terms, sky
// still left out) gives 0.060 there. The bound, 0.048, sits between: 37% above the guided
// upsample for drivers and noise, 20% below bilinear.
// (Measured the same way: the Cornell box 0.027 guided, 0.038 bilinear; but two-rooms 0.058
// guided, 0.054 bilinear: there the guide does not help yet, not understood.)
TEST(GtaoUpsample, KeepsOcclusionOnItsSideOfSilhouettes) {
  if (!have_bunny()) GTEST_SKIP() << "../shared/data/mesh/bunny.obj is missing";
  const World world = load_example_world("stanford-bunny");
  const AoRender full = render_occlusion(world, kWidth, kHeight, gtao(1), {.frames = kFrames});
  const AoRender half = render_occlusion(world, kWidth, kHeight, gtao(0.5), {.frames = kFrames});
  EXPECT_EQ(full.validation_messages, 0u);
  EXPECT_EQ(half.validation_messages, 0u);
  const Difference d = half_against_full(full, half);
  std::printf("half against full resolution: beside depth edges %.4f (%zu pixels), elsewhere %.4f\n", d.edges,
              d.edge_pixels, d.elsewhere);
  ASSERT_GT(d.edge_pixels, 200u);  // the world has such edges in view
  EXPECT_LE(d.edges, 0.048);
}

}  // namespace
}  // namespace lg::test
