// gi.lpv's propagation model on the CPU (nodes/gi/lpv/lpv_model.h): where light goes in one
// step, how much of it, and that the geometry volume stops it.
#include "nodes/gi/lpv/lpv_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/common.hpp>
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

// A virtual point light (a Lambertian emitter of power 1 facing +x, as injection makes it) in an
// empty volume. Its SH L1 lobe, 1/pi (0.25 + 0.5 cos theta), dips below zero behind it; the step
// clamps what each face receives at zero, which gains power. The gain in closed form, with the
// lobe's values at each face's direction (cos = 1, 0.894 on the far and side faces of the +x
// neighbour; 0, +-0.447 and 0 on those of the four lateral ones; the -x neighbour receives
// nothing): [0.40067 x 0.75 + 4 x 0.42343 x 0.69721 + 4 x (0.40067 x 0.25 + 0.42343 x
// (0.47361 + 0.02639 + 2 x 0.25))] / pi = 1.13821. Nothing may flow backwards, and light
// spreads symmetrically about the normal.
TEST(LpvModel, AVirtualPointLightFlowsAlongItsNormal) {
  LpvVolume v({9, 9, 9});
  const glm::ivec3 centre(4);
  const ShL1 lobe = sh_l1_cosine_lobe({1, 0, 0});
  for (int k = 0; k < 4; ++k) v.light[v.index(centre)][0][k] = lobe[k] / std::numbers::pi;
  ASSERT_NEAR(power(v, 0), 1.0, 1e-12);
  const LpvVolume after = propagate_step(v, false);
  const double far = 4.0 * std::asin(0.1), side = std::numbers::pi / 6.0 - std::asin(0.1);
  const double c = 1.0 / std::sqrt(1.25);  // cos theta towards the +x neighbour's side faces
  const double expected = (far * 0.75 + 4 * side * (0.25 + 0.5 * c) +
                           4 * (far * 0.25 + side * ((0.25 + 0.25 * c) + (0.25 - 0.25 * c) + 0.5))) /
                          std::numbers::pi;
  EXPECT_NEAR(power(after, 0), expected, 1e-9);
  EXPECT_NEAR(expected, 1.13821, 1e-5);
  auto at = [&](glm::ivec3 d) { return sh_l1_power(after.light[after.index(centre + d)][0]); };
  EXPECT_EQ(at({-1, 0, 0}), 0.0);
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

}  // namespace
}  // namespace lg
