// The split-sum DFG reference on the CPU: its two quadratures agree, a mirror reflects all
// (A + B = 1 at roughness 0), and known limits hold.
#include "nodes/env/brdf_lut/dfg_reference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lg::test {
namespace {

// The light-direction rule converges where the lobe is wide (1e-6 between 1024 and 4096
// steps at n.v = 1/31, roughness 0.42): the two agree to 2e-4 there.
TEST(DfgReference, VisibleNormalAndLightQuadraturesAgree) {
  for (double roughness : {0.4, 0.6, 0.8, 1.0})
    for (double n_dot_v : {1.0 / 31, 0.1, 0.5, 0.9}) {
      const glm::dvec2 a = dfg_reference(n_dot_v, roughness, 256);
      const glm::dvec2 b = dfg_reference_over_light(n_dot_v, roughness, 1024);
      const double tolerance = 2e-4;
      EXPECT_NEAR(a.x, b.x, tolerance) << roughness << " " << n_dot_v;
      EXPECT_NEAR(a.y, b.y, tolerance) << roughness << " " << n_dot_v;
    }
}

TEST(DfgReference, ScalePlusBiasTendsToOneAsRoughnessTendsToZero) {
  for (double n_dot_v : {0.05, 0.3, 1.0}) {
    const glm::dvec2 mirror = dfg_reference(n_dot_v, 0.0, 64);
    EXPECT_NEAR(mirror.x + mirror.y, 1.0, 1e-12) << n_dot_v;
    EXPECT_NEAR(mirror.y, std::pow(1 - n_dot_v, 5), 1e-12) << n_dot_v;  // Schlick at v.h = n.v
    EXPECT_GT(dfg_reference(n_dot_v, 0.02, 64).x + dfg_reference(n_dot_v, 0.02, 64).y, 0.995);
  }
}

}  // namespace
}  // namespace lg::test
