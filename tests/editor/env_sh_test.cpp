// L2 SH of equirectangular images: exact texel solid angles, projection and reconstruction.
#include "editor/env_sh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace lg {
namespace {

std::vector<float> image_of(uint32_t w, uint32_t h, const std::function<Vec3d(const Vec3d&)>& radiance) {
  std::vector<float> rgba(size_t(w) * h * 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const Vec3d l = radiance(equirect_direction((x + 0.5) / w, (y + 0.5) / h));
      float* t = &rgba[(size_t(y) * w + x) * 4];
      t[0] = float(l[0]), t[1] = float(l[1]), t[2] = float(l[2]), t[3] = 1;
    }
  return rgba;
}

TEST(EnvSh, TexelSolidAnglesSumToTheSphereAtAnySize) {
  for (auto [w, h] : {std::pair{1u, 1u}, {7u, 3u}, {512u, 256u}, {8192u, 4096u}}) {
    double sum = 0;
    for (uint32_t row = 0; row < h; ++row) sum += w * equirect_texel_solid_angle(row, w, h);
    EXPECT_NEAR(sum, 4 * std::numbers::pi, 1e-9) << w << "x" << h;
  }
}

TEST(EnvSh, DirectionsAndUvAreInverses) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u01(0.001, 0.999);
  for (int i = 0; i < 200; ++i) {
    const double u = u01(rng), v = u01(rng);
    const auto uv = equirect_uv(equirect_direction(u, v));
    EXPECT_NEAR(uv[0], u, 1e-12);
    EXPECT_NEAR(uv[1], v, 1e-12);
  }
  EXPECT_NEAR(equirect_direction(0.3, 0)[1], 1, 1e-12);  // the top row is +Y
}

TEST(EnvSh, ConstantRadianceIsBandZeroOnly) {
  const auto rgba = image_of(128, 64, [](const Vec3d&) { return Vec3d{2, 3, 5}; });
  const ShL2 sh = project_equirect_sh_l2(128, 64, rgba);
  const double c0 = 2 * std::sqrt(std::numbers::pi);  // integral of Y00 over the sphere
  EXPECT_NEAR(sh.rgb[0][1], 3 * c0, 1e-9);
  // Higher bands vanish up to the error of sampling texel centres (0.1% of band 0 here).
  for (int k = 1; k < 9; ++k) EXPECT_NEAR(sh.rgb[k][0], 0, 5e-3) << k;
  const Vec3d back = evaluate_sh_l2(sh, {0, 0.6, 0.8});
  EXPECT_NEAR(back[2], 5, 2e-3);
}

TEST(EnvSh, RandomL2FunctionsProjectBackToTheirCoefficients) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0, 1);
  ShL2 truth;
  for (auto& c : truth.rgb) c = {normal(rng), normal(rng), normal(rng)};
  const auto rgba = image_of(512, 256, [&](const Vec3d& d) { return evaluate_sh_l2(truth, d); });
  const ShL2 sh = project_equirect_sh_l2(512, 256, rgba);
  for (int k = 0; k < 9; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh.rgb[k][c], truth.rgb[k][c], 2e-3) << "k " << k << " c " << c;
}

TEST(EnvSh, NonFiniteTexelsAreSkipped) {
  auto rgba = image_of(64, 32, [](const Vec3d&) { return Vec3d{1, 1, 1}; });
  auto without = rgba;
  for (size_t texel : {100, 200}) {
    rgba[4 * texel + texel % 3] =
        texel == 100 ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
    for (int c = 0; c < 3; ++c) without[4 * texel + c] = 0;
  }
  const ShL2 sh = project_equirect_sh_l2(64, 32, rgba), expected = project_equirect_sh_l2(64, 32, without);
  for (int k = 0; k < 9; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(sh.rgb[k][c], expected.rgb[k][c]);
}

}  // namespace
}  // namespace lg
