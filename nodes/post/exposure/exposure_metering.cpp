#include "nodes/post/exposure/exposure_metering.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lg {

void check_exposure_settings(const ExposureSettings& s, const std::string& where) {
  if (!(s.low_percent < s.high_percent))
    throw std::invalid_argument(where + ": low_percent (" + std::to_string(s.low_percent) +
                                ") must be below high_percent (" + std::to_string(s.high_percent) + ")");
  if (!(s.histogram_min < s.histogram_max))
    throw std::invalid_argument(where + ": histogram_min must be below histogram_max");
}

double exposure_luminance(double r, double g, double b) {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

int exposure_bin(double luminance, const ExposureSettings& s) {
  const double ev = std::log2(std::max(luminance, std::exp2(s.histogram_min)));
  const double t = std::floor((ev - s.histogram_min) / (s.histogram_max - s.histogram_min) * kExposureBins);
  return int(std::clamp(t, 0.0, double(kExposureBins - 1)));
}

ExposureHistogram exposure_histogram(std::span<const float> rgba, const ExposureSettings& s) {
  ExposureHistogram h{};
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (!std::isfinite(rgba[i]) || !std::isfinite(rgba[i + 1]) || !std::isfinite(rgba[i + 2])) continue;
    ++h[size_t(exposure_bin(exposure_luminance(rgba[i], rgba[i + 1], rgba[i + 2]), s))];
  }
  return h;
}

double metered_log2_luminance(const ExposureHistogram& h, const ExposureSettings& s) {
  double total = 0;
  for (uint64_t c : h) total += double(c);
  const double lo = total * s.low_percent / 100, hi = total * s.high_percent / 100;
  const double bin_width = (s.histogram_max - s.histogram_min) / kExposureBins;
  double below = 0, sum = 0, weight = 0;
  for (int b = 0; b < kExposureBins; ++b) {
    const double count = double(h[size_t(b)]);
    const double w = std::max(0.0, std::min(below + count, hi) - std::max(below, lo));
    sum += w * (s.histogram_min + (b + 0.5) * bin_width);
    weight += w;
    below += count;
  }
  return weight > 0 ? sum / weight : 0.5 * (s.histogram_min + s.histogram_max);
}

double target_exposure(double metered, const ExposureSettings& s) {
  return std::log2(kExposureMiddleGrey) - metered + s.compensation;
}

double adapt_exposure(double previous, double target, double seconds, const ExposureSettings& s) {
  return previous + std::clamp(target - previous, -s.speed_down * seconds, s.speed_up * seconds);
}

}  // namespace lg
