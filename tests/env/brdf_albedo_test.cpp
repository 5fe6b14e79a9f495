// nodes/env/brdf_lut/brdf_albedo_table.inc against the reference it was generated from, and
// its bilinear reading at and between texels.
#include "nodes/env/brdf_lut/brdf_albedo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lg::test {
namespace {

// Texels across the table, corners and the grazing, mirror-like edge included. 2e-7: the file's
// seven decimals.
TEST(BrdfAlbedo, TableMatchesTheReference) {
  constexpr int last = kBrdfAlbedoSize - 1;
  for (const auto& [i, j] : {std::pair{0, 0}, {last, 0}, {0, last}, {last, last}, {1, 3}, {7, 19}, {20, 11}, {3, 28}}) {
    const double n_dot_v = std::pow(double(i) / last, 4.0);
    const glm::dvec2 expected = brdf_albedo_reference(n_dot_v, double(j) / last);
    const glm::dvec2 stored = brdf_albedo_lookup(n_dot_v, double(j) / last);
    EXPECT_NEAR(stored.x, expected.x, 2e-7) << "texel " << i << ", " << j;
    EXPECT_NEAR(stored.y, expected.y, 2e-7) << "texel " << i << ", " << j;
  }
}

// Between texels the table is within 1% of the white albedo A + B everywhere the furnace reads
// it (the criterion the lighting tests hold the BRDF to); measured at texel midpoints, the
// first column, where a near-mirror's albedo turns at grazing views, included.
TEST(BrdfAlbedo, BilinearReadingStaysWithinAPercent) {
  constexpr int last = kBrdfAlbedoSize - 1;
  double worst = 0.0;
  for (int j = 0; j < last; j += 5)
    for (int i : {3, 4, 5, 6, 8, 16, 30}) {
      const double n_dot_v = std::pow((i + 0.5) / last, 4.0), roughness = (j + 0.5) / last;
      const glm::dvec2 expected = brdf_albedo_reference(n_dot_v, roughness, 64);
      const glm::dvec2 read = brdf_albedo_lookup(n_dot_v, roughness);
      worst = std::max(worst, std::abs((read.x + read.y) / (expected.x + expected.y) - 1.0));
    }
  std::printf("albedo table between texels: max relative error %.5f\n", worst);
  EXPECT_LE(worst, 0.01);
}

}  // namespace
}  // namespace lg::test
