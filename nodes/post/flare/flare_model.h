// post.flare's model, stated once: its settings, the ghosts' sizes, and the whole flare
// evaluated on the CPU in double precision. The kernel takes its settings and tables from here
// and its shaders compute the same formulas, so the tests and the benchmark compare the GPU
// against this (lens flare has no physical ground truth here: the reference is the model at
// full resolution). The model:
//   bright    B: the image's part above `threshold` (luminance, soft knee as post.bloom's),
//              NaN/Inf as 0, averaged over divisor x divisor blocks (the low-res grid).
//   features  F = (wg G + wh H + ws S) / max(1, wg + wh + ws) on that grid, each feature a
//              normalised-weight resampling of B:
//              G ghosts: B mirrored/scaled through the centre (size kFlareGhostScales[i], per
//                channel x (1 + chromatic), 1, (1 - chromatic)), the density divided by the
//                size squared, windowed by (1 - t)^2 (t: the source's distance from the centre,
//                1 at a corner), averaged over the ghosts;
//              H halo: B at the point halo_radius nearer the centre along the line to it, the
//                density scaled by |r - R| / r (the ring's stretch) and 1/2 (two branches),
//                windowed by (1 - rho / R)^2 (rho: the source's distance from the centre);
//              S streaks: `streaks` lines through each texel (evenly spaced angles from the
//                horizontal), each a blur with weights exp(-4 |j| / J), summing to 1, over
//                2J + 1 taps streak_length x width long; averaged over the lines.
//   guard     F scaled by min(1, sum B / sum F) per channel (the smallest), so that the flare
//              never holds more energy than the bright part it comes from: the features are
//              normalised but point sampling a texel-sized source can overshoot a little.
//   composite out = in + intensity F, upsampled bilinearly with the texel centres clamped;
//              over the blocks' area each low-res texel's weights sum to exactly divisor^2,
//              so the added energy is intensity x divisor^2 x sum F <= intensity x the energy
//              above the threshold (pixels past the last whole block get no flare).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace lg {

inline constexpr int kFlareMaxGhosts = 8;
// Each ghost's size against the image; negative: mirrored through the centre. Sizes away from
// +-1 keep the ghosts apart from the light and from each other.
inline constexpr std::array<float, kFlareMaxGhosts> kFlareGhostScales = {-0.55f, -1.15f, 0.4f,  -0.3f,
                                                                         0.75f,  -1.7f,  0.25f, -0.85f};
inline constexpr int kFlareMaxStreakTaps = 16;  // J's most, each side of the texel

struct FlareSettings {
  double intensity = 0.01;  // share of the energy above the threshold added back
  double threshold = 10;    // luminance, cd/m^2
  int divisor = 4;          // 1 / resolution_scale
  int ghosts = 4;
  double ghost_weight = 0.6, halo_weight = 0.2, streak_weight = 0.2;
  double halo_radius = 0.35;    // in image heights
  int streaks = 2;              // lines through each bright texel
  double streak_length = 0.06;  // in image widths, each side
  double chromatic = 0.04;      // the ghosts' relative size step from red to blue
};

// The low-res grid's size for a frame: W / divisor rounded down (the compiler's rule for a
// resource at scale 1 / divisor), at least 1.
uint32_t flare_grid_size(uint32_t frame, int divisor);
// The features' weights (ghost, halo, streak) divided by max(1, their sum).
std::array<double, 3> flare_feature_weights(const FlareSettings& s);
// The streak's taps each side: ceil(length in texels) within 1..kFlareMaxStreakTaps.
int flare_streak_taps(double length_texels);

struct FlareResult {
  std::vector<float> rgba;  // the image with the flare added, 4 floats a pixel
  uint32_t grid_width = 0, grid_height = 0;
  std::array<double, 3> bright_energy{};   // per channel: the sum over pixels of the bright part
  std::array<double, 3> feature_energy{};  // per channel: divisor^2 x sum F before the guard
  double guard = 1;                        // the factor the guard applied
};

// The model on `rgba` (width x height, 4 floats a pixel).
FlareResult evaluate_flare(std::span<const float> rgba, uint32_t width, uint32_t height, const FlareSettings& s);

}  // namespace lg
