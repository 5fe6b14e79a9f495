// post.exposure's CPU reference by hand: bins, the metered window, the exposure and adaptation.
#include "nodes/post/exposure/exposure_metering.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lg {
namespace {

TEST(ExposureMetering, BinsCoverTheRangeAndClampOutside) {
  const ExposureSettings s;  // [-16, 16] in 256 bins of 1/8 EV
  EXPECT_EQ(exposure_bin(1.0, s), 128);
  EXPECT_EQ(exposure_bin(std::exp2(-16.0), s), 0);
  EXPECT_EQ(exposure_bin(0.0, s), 0);
  EXPECT_EQ(exposure_bin(-3.0, s), 0);
  EXPECT_EQ(exposure_bin(std::exp2(15.99), s), 255);
  EXPECT_EQ(exposure_bin(1e30, s), 255);
}

TEST(ExposureMetering, NonFinitePixelsAreNotCounted) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float rgba[] = {1, 1, 1, 1, nan, 1, 1, 1, 1, inf, 1, 1, 1, 1, -inf, 1};
  const ExposureHistogram h = exposure_histogram(rgba, ExposureSettings{});
  uint64_t total = 0;
  for (uint64_t c : h) total += c;
  EXPECT_EQ(total, 1u);
}

// Ten pixels, one per bin 100..109: the 50-95% window covers bins 105..108 and half of 109.
TEST(ExposureMetering, TheWindowWeighsPartlyCoveredBinsByTheirShare) {
  ExposureSettings s;
  ExposureHistogram h{};
  for (int b = 100; b < 110; ++b) h[size_t(b)] = 1;
  auto centre = [&](int b) { return -16 + (b + 0.5) / 8; };
  const double expected = (centre(105) + centre(106) + centre(107) + centre(108) + 0.5 * centre(109)) / 4.5;
  EXPECT_NEAR(metered_log2_luminance(h, s), expected, 1e-12);
  EXPECT_NEAR(target_exposure(expected, s), std::log2(0.18) - expected, 1e-12);
  s.compensation = 2;
  EXPECT_NEAR(target_exposure(expected, s), std::log2(0.18) - expected + 2, 1e-12);
}

TEST(ExposureMetering, AnEmptyHistogramMetersTheMiddleOfTheRange) {
  EXPECT_EQ(metered_log2_luminance(ExposureHistogram{}, ExposureSettings{}), 0.0);
}

TEST(ExposureMetering, AdaptationIsLimitedByTheSpeedOfItsDirection) {
  const ExposureSettings s;  // 1 EV/s up, 3 EV/s down
  EXPECT_DOUBLE_EQ(adapt_exposure(0, 5, 0.5, s), 0.5);
  EXPECT_DOUBLE_EQ(adapt_exposure(0, -5, 0.5, s), -1.5);
  EXPECT_DOUBLE_EQ(adapt_exposure(0, 0.2, 0.5, s), 0.2);  // reached: no overshoot
}

TEST(ExposureMetering, ContradictorySettingsNameTheNode) {
  ExposureSettings s;
  s.low_percent = 95, s.high_percent = 50;
  try {
    check_exposure_settings(s, "post.exposure 'exp'");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'exp'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("low_percent"), std::string::npos);
  }
}

}  // namespace
}  // namespace lg
