// post.exposure's arithmetic on the CPU: the log2-luminance histogram, the metered average
// between two percentiles, the exposure it asks for and one step of adaptation. The reference
// the GPU passes are tested against (same bins, same rules, in double precision); the kernel
// takes its settings from here so the two cannot drift apart.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace lg {

inline constexpr int kExposureBins = 256;            // nodes/post/exposure/shaders/exposure_common.glsl
inline constexpr double kExposureMiddleGrey = 0.18;  // the metered average maps to this

struct ExposureSettings {
  double histogram_min = -16, histogram_max = 16;  // log2 luminance covered by the bins
  double low_percent = 50, high_percent = 95;      // the metered window, darkest pixels first
  double compensation = 0;                         // EV added to the metered exposure
  double speed_up = 1, speed_down = 3;             // EV per second while exposure rises / falls
};

// Throws std::invalid_argument naming `where` when the window is empty or the range inverted.
void check_exposure_settings(const ExposureSettings& s, const std::string& where);

using ExposureHistogram = std::array<uint64_t, kExposureBins>;

// Rec. 709 luminance.
double exposure_luminance(double r, double g, double b);
// The bin of a luminance: luminances at or below 2^histogram_min fall in the first bin, those
// above the range in the last. Callers skip non-finite pixels.
int exposure_bin(double luminance, const ExposureSettings& s);
// The histogram of RGBA texels (4 floats each); pixels with a NaN or infinite channel are left
// out, so they never reach the exposure.
ExposureHistogram exposure_histogram(std::span<const float> rgba, const ExposureSettings& s);
// The average log2 luminance of the pixels between low_percent and high_percent of the count
// (darkest first), each bin at its centre and partly covered bins by their covered share; the
// middle of the range when no pixel counts (an image of NaN only).
double metered_log2_luminance(const ExposureHistogram& h, const ExposureSettings& s);
// The exposure in EV (log2 of the factor on radiance) that maps the metered average to middle
// grey, plus the compensation.
double target_exposure(double metered_log2_luminance, const ExposureSettings& s);
// One frame of adaptation from `previous` toward `target` (both EV) after `seconds`: at most
// speed_up * seconds upward and speed_down * seconds downward.
double adapt_exposure(double previous, double target, double seconds, const ExposureSettings& s);

}  // namespace lg
