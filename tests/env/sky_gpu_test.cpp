// env.sky's pass on lavapipe against the double-precision reference (the same model, each
// texel integrated by 4x4 Gauss points on each 1/64 of a face, the sun disk by 16384 points):
// sky texels within 3e-3 relative on faces over 4 texels (measured 2.3e-3 on mip 0, where the
// GPU takes the centre alone; half precision alone rounds by up to 4.9e-4) and 1e-2 on smaller
// ones (measured 5.4e-3 at 1x1, an 8x8 point mean over a face), the sun's energy in each mip
// within 2e-3 of the disk's (measured 9e-4), the sun in the right texel; then the
// stress cases (a sun 1e5 times the sky, the sun below the horizon, turbidity at its bounds).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>

#include "nodes/env/sky/sky_kernel.h"
#include "nodes/env/sky/sky_model.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image.h"
#include "tests/env/env_test_support.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

class SkyGpuTest : public GpuTest {
 protected:
  std::vector<CubeImage> render(const SkyModel& model, uint32_t size) {
    uint32_t mips = 1;
    while ((size >> mips) > 0) ++mips;
    Image cube = make_cube(context(), "sky", size, mips);
    submitter().run([&](VkCommandBuffer cmd) {
      image_barrier(cmd, cube, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      record_sky(context(), pipelines(), cmd, "sky/render", model, cube);
      memory_barrier(cmd);
    });
    std::vector<CubeImage> out;
    for (uint32_t m = 0; m < mips; ++m) out.push_back(read_cube(submitter(), cube, m, VK_IMAGE_LAYOUT_GENERAL));
    return out;
  }

  // Texels whose centre is within this angle of the sun hold sun energy.
  static bool near_sun(const CubeImage& c, int f, uint32_t i, uint32_t j, const glm::dvec3& sun) {
    const double texel_angle = 2.0 / c.size * 1.5;
    return glm::dot(c.direction(f, i, j), sun) > std::cos(texel_angle + kSunAngularRadius);
  }
};

TEST_F(SkyGpuTest, EveryMipMatchesTheReference) {
  const SkyModel model = make_sky_model({{0.3, 0.6, 0.4}, 20, 3});
  const std::vector<CubeImage> gpu = render(model, 64);
  for (const CubeImage& mip : gpu) {
    const CubeImage ref = render_sky_reference(model, mip.size, 64 / mip.size);
    double worst = 0, sun_gpu = 0, sun_ref = 0;
    for (int f = 0; f < 6; ++f)
      for (uint32_t j = 0; j < mip.size; ++j)
        for (uint32_t i = 0; i < mip.size; ++i) {
          const double omega = texel_solid_angle(mip.size, i, j);
          if (mip.size > 4 && near_sun(mip, f, i, j, model.sun)) {
            sun_gpu += omega * mip.at(f, i, j).y, sun_ref += omega * ref.at(f, i, j).y;
            continue;
          }
          for (int c = 0; c < 3; ++c) {
            double e = std::abs(mip.at(f, i, j)[c] - ref.at(f, i, j)[c]) / ref.at(f, i, j)[c];
            worst = std::max(worst, e);
          }
        }
    std::cout << "mip " << mip.size << "^2: sky max relative error " << worst;
    EXPECT_LE(worst, mip.size > 4 ? 3e-3 : 1e-2) << mip.size;
    if (mip.size > 4) {
      std::cout << ", energy near the sun " << sun_gpu << " against " << sun_ref;
      EXPECT_NEAR(sun_gpu, sun_ref, 2e-3 * sun_ref) << mip.size;
    }
    std::cout << "\n";
  }
  // The brightest texel of mip 0 is the one the sun direction hits.
  const CubeCoord c = cube_coord(model.sun);
  const CubeImage& top = gpu[0];
  size_t brightest = 0;
  for (size_t t = 0; t < top.texels.size(); ++t)
    if (top.texels[t].y > top.texels[brightest].y) brightest = t;
  EXPECT_EQ(brightest, (size_t(c.face) * 64 + uint32_t(c.v * 64)) * 64 + uint32_t(c.u * 64));
}

TEST_F(SkyGpuTest, ZenithIsOneAndTheSunCarriesItsEnergy) {
  const SkyModel model = make_sky_model({{0.0, 1.0, 0.0}, 20, 3});
  // The zenith's luminance is 1 by construction.
  const SkyModel off = make_sky_model({{0.0, 0.2, 1.0}, 0, 3});
  const glm::dvec3 c = sky_radiance(off, {0, 1, 0});
  EXPECT_NEAR(0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z, 1.0, 2e-3);  // Rec.709 luminance
  // Every mip integrates to the same radiant energy (sky and sun).
  const std::vector<CubeImage> gpu = render(model, 32);
  const glm::dvec3 total = integrate(gpu[0]);
  for (const CubeImage& mip : gpu)
    EXPECT_LT(glm::length(integrate(mip) - total), 3e-3 * glm::length(total)) << mip.size;
}

TEST_F(SkyGpuTest, StressStaysFiniteAndBounded) {
  struct Case {
    SkyParams params;
    const char* what;
  };
  const Case cases[] = {{{{0.3, 0.6, 0.4}, 1e5, 3}, "sun 1e5 x sky"},
                        {{{0.3, -0.2, 0.4}, 20, 3}, "sun below the horizon"},
                        {{{0.0, 0.0, 0.0}, 20, 3}, "zero sun direction"},
                        {{{0.0, 1.0, 0.0}, 20, 1.7}, "turbidity 1.7"},
                        {{{1.0, 0.05, 0.0}, 20, 10}, "turbidity 10, low sun"}};
  for (const Case& k : cases) {
    const SkyModel model = make_sky_model(k.params);
    const std::vector<CubeImage> gpu = render(model, 32);
    for (const CubeImage& mip : gpu)
      for (const glm::dvec4& t : mip.texels)
        for (int c = 0; c < 3; ++c) {
          ASSERT_TRUE(std::isfinite(t[c]) && t[c] >= 0 && t[c] <= 65504) << k.what << " mip " << mip.size;
        }
    if (model.sun.y < 0) {  // no sun energy: the sky alone
      const CubeImage ref = render_sky_reference(model, 32, 1);
      EXPECT_LT(glm::length(integrate(gpu[0]) - integrate(ref)), 2e-3 * glm::length(integrate(ref))) << k.what;
      EXPECT_LT(integrate(gpu[0]).y, integrate(render_sky_reference(model, 32, 1, 0)).y * 1.002);
    }
  }
}

}  // namespace
}  // namespace lg::test
