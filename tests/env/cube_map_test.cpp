// The cube-map and equirectangular conventions on the CPU: face centres and orientation, the
// direction round trip, exact texel solid angles, and area-correct mips.
#include "nodes/env/common/cube_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>

#include "nodes/env/common/equirect.h"
#include "tests/env/env_test_support.h"

namespace lg::test {
namespace {

TEST(CubeMapConvention, FacesAreInVulkanOrderWithVulkanOrientation) {
  const glm::dvec3 centres[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // Where u = 1 (the right edge) and v = 1 (the bottom row) point on each face, from the spec's
  // table of (sc, tc) per major axis.
  const glm::dvec3 right[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
  const glm::dvec3 down[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_LT(glm::length(cube_direction(f, 0.5, 0.5) - centres[f]), 1e-15) << f;
    EXPECT_LT(glm::length(cube_direction(f, 1.0, 0.5) - glm::normalize(centres[f] + right[f])), 1e-15) << f;
    EXPECT_LT(glm::length(cube_direction(f, 0.5, 1.0) - glm::normalize(centres[f] + down[f])), 1e-15) << f;
  }
}

TEST(CubeMapConvention, DirectionsRoundTripThroughFaceCoordinates) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 10000; ++k) {
    const int face = int(rng() % 6);
    const double u = unit(rng), v = unit(rng);
    const CubeCoord c = cube_coord(cube_direction(face, u, v) * (0.5 + unit(rng)));
    ASSERT_EQ(c.face, face);
    ASSERT_NEAR(c.u, u, 1e-12);
    ASSERT_NEAR(c.v, v, 1e-12);
  }
}

TEST(CubeMapConvention, TexelSolidAnglesAreExact) {
  for (uint32_t size : {1u, 2u, 7u, 64u}) {
    double sum = 0;
    for (uint32_t j = 0; j < size; ++j)
      for (uint32_t i = 0; i < size; ++i) sum += texel_solid_angle(size, i, j);
    EXPECT_NEAR(6 * sum, 4 * std::numbers::pi, 1e-12) << size;
  }
  // Against a fine midpoint quadrature of the Jacobian 1 / (1 + x^2 + y^2)^1.5 over one texel.
  const uint32_t size = 8, i = 6, j = 1;
  double quadrature = 0;
  const int n = 400;
  const double h = 2.0 / size / n;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const double x = -1 + 2.0 * i / size + (a + 0.5) * h, y = -1 + 2.0 * j / size + (b + 0.5) * h;
      quadrature += h * h / std::pow(1 + x * x + y * y, 1.5);
    }
  EXPECT_NEAR(texel_solid_angle(size, i, j), quadrature, 1e-8);
}

TEST(CubeMapConvention, MipsKeepTheIntegralOfRadiance) {
  const std::vector<CubeImage> mips = mip_chain(random_environment(32, 5));
  ASSERT_EQ(mips.size(), 6u);
  const glm::dvec3 total = integrate(mips[0]);
  for (const CubeImage& mip : mips)
    EXPECT_LT(glm::length(integrate(mip) - total), 1e-12 * glm::length(total)) << mip.size;
}

TEST(EquirectConvention, CentreLooksDownMinusZAndTopIsUp) {
  EXPECT_LT(glm::length(equirect_direction({0.5, 0.5}) - glm::dvec3(0, 0, -1)), 1e-15);
  EXPECT_LT(glm::length(equirect_direction({0.75, 0.5}) - glm::dvec3(1, 0, 0)), 1e-15);
  EXPECT_NEAR(equirect_direction({0.3, 0.0}).y, 1.0, 1e-15);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const glm::dvec2 uv(unit(rng), 0.01 + 0.98 * unit(rng));
    const glm::dvec2 back = equirect_uv(equirect_direction(uv));
    ASSERT_NEAR(back.x, uv.x, 1e-12);
    ASSERT_NEAR(back.y, uv.y, 1e-12);
  }
}

}  // namespace
}  // namespace lg::test
