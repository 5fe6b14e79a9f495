// gi.lpv's propagation model on the CPU (nodes/gi/lpv/lpv_model.h): where light goes in one
// step, how much of it, and that the geometry volume stops it.
#include "nodes/gi/lpv/lpv_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {
namespace {

double power(const LpvVolume& v, int channel) {
  double sum = 0;
  for (const auto& cell : v.light) sum += sh_l1_power(cell[channel]);
  return sum;
}

// An isotropic source (intensity 1 W/sr, power 4 pi) in an empty volume: one step puts exactly
// a sixth of its power into each face neighbour and nothing anywhere else. The five faces a
// neighbour receives through subtend 2 pi / 3 together, so the power is kept to rounding
// (1e-12 relative: doubles, a few dozen operations).
TEST(LpvModel, AnIsotropicSourceKeepsItsPowerInOneStep) {
  LpvVolume v({7, 7, 7});
  const glm::ivec3 centre(3);
  v.light[v.index(centre)][1] = {1.0 / 0.28209479177387814, 0, 0, 0};
  const double before = power(v, 1);
  ASSERT_NEAR(before, 4.0 * std::numbers::pi, 1e-12);
  const LpvVolume after = propagate_step(v, false);
  EXPECT_NEAR(power(after, 1), before, 1e-12 * before);
  EXPECT_EQ(power(after, 0), 0.0);
  for (int z = 0; z < 7; ++z)
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 7; ++x) {
        const glm::ivec3 c(x, y, z);
        const glm::ivec3 d = glm::abs(c - centre);
        const double p = sh_l1_power(after.light[after.index(c)][1]);
        if (d.x + d.y + d.z == 1)
          EXPECT_NEAR(p, before / 6.0, 1e-12 * before) << x << "," << y << "," << z;
        else
          EXPECT_EQ(p, 0.0) << x << "," << y << "," << z;
      }
}

// The L1 coefficients read as a lobe (sh_l1_lobe): a cosine lobe and an isotropic source read
// back exactly, and a cosine lobe's irradiance on a surface facing it is 2 pi / 3 (the integral of
// cos^2 over the hemisphere), on one turned away 0, where the L1 series gives pi / 12 of light
// on it from behind.
TEST(LpvModel, TheCoefficientsReadAsALobe) {
  const ShLobe lobe = sh_l1_lobe(sh_l1_cosine_lobe(glm::normalize(glm::dvec3(1, 2, -2))));
  EXPECT_NEAR(lobe.a, 0.0, 1e-12);
  EXPECT_NEAR(lobe.b, 1.0, 1e-12);
  EXPECT_NEAR(glm::length(lobe.d - glm::normalize(glm::dvec3(1, 2, -2))), 0.0, 1e-12);
  const ShLobe isotropic = sh_l1_lobe({1.0 / 0.28209479177387814, 0, 0, 0});
  EXPECT_NEAR(isotropic.a, 1.0, 1e-12);
  EXPECT_EQ(isotropic.b, 0.0);
  const ShLobe up = sh_l1_lobe(sh_l1_cosine_lobe({0, 1, 0}));
  EXPECT_NEAR(sh_lobe_irradiance(up, {0, -1, 0}), 2.0 * std::numbers::pi / 3.0, 1e-12);
  EXPECT_NEAR(sh_lobe_irradiance(up, {0, 1, 0}), 0.0, 1e-12);
}

// A virtual point light (a Lambertian emitter of power 1 facing +x, as injection makes it) in an
// empty volume: one step keeps its power (to 1e-12: doubles; without the outflow scale it keeps
// 0.851), nothing flows backwards (below 1e-15 of it: rounding in the lobe's direction), and
// light spreads symmetrically about the normal, most of it straight on.
TEST(LpvModel, AVirtualPointLightKeepsItsPowerAndFlowsAlongItsNormal) {
  LpvVolume v({9, 9, 9});
  const glm::ivec3 centre(4);
  const ShL1 lobe = sh_l1_cosine_lobe({1, 0, 0});
  for (int k = 0; k < 4; ++k) v.light[v.index(centre)][0][k] = lobe[k] / std::numbers::pi;
  ASSERT_NEAR(power(v, 0), 1.0, 1e-12);
  const LpvVolume after = propagate_step(v, false);
  EXPECT_NEAR(power(after, 0), 1.0, 1e-12);
  EXPECT_NEAR(sh_lobe_sampled_outflow({1, 0, 0}) / std::numbers::pi, 0.85086, 1e-5);
  auto at = [&](glm::ivec3 d) { return sh_l1_power(after.light[after.index(centre + d)][0]); };
  EXPECT_LT(std::abs(at({-1, 0, 0})), 1e-15);
  EXPECT_GT(at({1, 0, 0}), 2.0 * at({0, 1, 0}));
  EXPECT_NEAR(at({0, 1, 0}), at({0, -1, 0}), 1e-12);
  EXPECT_NEAR(at({0, 1, 0}), at({0, 0, 1}), 1e-12);
  EXPECT_NEAR(at({0, 0, 1}), at({0, 0, -1}), 1e-12);
}

// A wall of cells across x = 4 whose occlusion blocks light from every direction twice over (so
// the mean with a clear neighbour still blocks all): an isotropic source at x = 2 lights nothing
// beyond the wall in 6 steps (summed over the steps), where without the occlusion more than 1% of
// its power does.
TEST(LpvModel, AnOccludingWallStopsTheLight) {
  LpvVolume v({9, 5, 5});
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 5; ++y) v.occlusion[v.index({4, y, z})] = {2.0 / 0.28209479177387814, 0, 0, 0};
  v.light[v.index({2, 2, 2})][2] = {1.0 / 0.28209479177387814, 0, 0, 0};
  auto beyond_the_wall = [](bool occlude, LpvVolume step) {
    double sum = 0;
    for (int i = 0; i < 6; ++i) {
      step = propagate_step(step, occlude);
      for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 5; ++y)
          for (int x = 5; x < 9; ++x) sum += sh_l1_power(step.light[step.index({x, y, z})][2]);
    }
    return sum;
  };
  EXPECT_EQ(beyond_the_wall(true, v), 0.0);
  EXPECT_GT(beyond_the_wall(false, v), 0.01 * 4.0 * std::numbers::pi);
}

// A surface's occlusion (a cosine lobe about its normal, blocking potential 1, as lpv_voxelize.comp
// adds a triangle that fills a cell) is read as a lobe: it blocks light that travels into the
// surface (half of it between its cell and a clear one: the two cells' mean) and none of the
// light that runs along it or leaves it. Read as the L1 series it blocked an eighth of the light
// along it (0.875 passed) and only 0.375 head-on.
TEST(LpvModel, ASurfaceBlocksLightIntoItNotAlongIt) {
  const ShL1 clear{}, surface = sh_l1_cosine_lobe({0, 1, 0});
  EXPECT_NEAR(lpv_transmittance(clear, surface, {0, -1, 0}), 0.5, 1e-9);
  EXPECT_NEAR(lpv_transmittance(surface, clear, {0, -1, 0}), 0.5, 1e-9);
  EXPECT_NEAR(lpv_transmittance(clear, surface, {1, 0, 0}), 1.0, 1e-9);
  EXPECT_NEAR(lpv_transmittance(clear, surface, {0, 0, -1}), 1.0, 1e-9);
  EXPECT_NEAR(lpv_transmittance(clear, surface, {0, 1, 0}), 1.0, 1e-9);
}

// The energy over many steps: a virtual point light (power 1, facing +x) in the middle of a
// 17^3 grid, whose light cannot reach the grid's faces in 7 steps (one cell a step), still has
// power 1 after each of them (1e-9: doubles over seven steps), however the light has spread and
// turned. Without the outflow scale a step loses up to 15% of a lobe along an axis (0.851, the
// test above), so light that reached a given distance in a finer grid, in more steps, had lost
// more of itself on the way (fails without it: 0.85 after the first step).
TEST(LpvModel, LightKeepsItsPowerOverManySteps) {
  LpvVolume v({17, 17, 17});
  const ShL1 lobe = sh_l1_cosine_lobe({1, 0, 0});
  for (int k = 0; k < 4; ++k) v.light[v.index(glm::ivec3(8))][0][k] = lobe[k] / std::numbers::pi;
  for (int step = 1; step <= 7; ++step) {
    v = propagate_step(v, false);
    EXPECT_NEAR(power(v, 0), 1.0, 1e-9) << "after step " << step;
  }
}

}  // namespace
}  // namespace lg
