#include "nodes/post/flare/flare_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lg {
namespace {

using Rgb = std::array<double, 3>;

// NaN and Inf as 0, the rest within rgba16f's finite range and not negative.
bool finite(const float* c) {
  return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
}

Rgb finite_radiance(const float* c) {
  if (!finite(c)) return {};
  return {std::clamp(double(c[0]), 0.0, 65504.0), std::clamp(double(c[1]), 0.0, 65504.0),
          std::clamp(double(c[2]), 0.0, 65504.0)};
}

// post.bloom's knee: the part of the luminance above the threshold, in the pixel's colour.
Rgb bright_part(Rgb c, double threshold) {
  if (threshold <= 0) return c;
  const double luminance = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  if (!(luminance > threshold)) return {};
  const double k = (luminance - threshold) / luminance;
  return {c[0] * k, c[1] * k, c[2] * k};
}

class Grid {
 public:
  Grid(uint32_t w, uint32_t h) : w_(int(w)), h_(int(h)), texels_(size_t(w) * h) {}
  int width() const { return w_; }
  int height() const { return h_; }
  Rgb& at(int x, int y) { return texels_[size_t(y) * w_ + x]; }
  const Rgb& at(int x, int y) const { return texels_[size_t(y) * w_ + x]; }

  // Bilinear at texel coordinates (centres at +0.5), indices clamped to the edge.
  double bilinear(double tx, double ty, int channel) const {
    tx = std::clamp(tx - 0.5, 0.0, double(w_ - 1));
    ty = std::clamp(ty - 0.5, 0.0, double(h_ - 1));
    const int x0 = int(tx), y0 = int(ty);
    const int x1 = std::min(x0 + 1, w_ - 1), y1 = std::min(y0 + 1, h_ - 1);
    const double fx = tx - x0, fy = ty - y0;
    return (1 - fy) * ((1 - fx) * at(x0, y0)[channel] + fx * at(x1, y0)[channel]) +
           fy * ((1 - fx) * at(x0, y1)[channel] + fx * at(x1, y1)[channel]);
  }
  // At uv in [0, 1]^2; 0 outside the image.
  double sample_uv(double u, double v, int channel) const {
    if (u < 0 || u > 1 || v < 0 || v > 1) return 0;
    return bilinear(u * w_, v * h_, channel);
  }

 private:
  int w_, h_;
  std::vector<Rgb> texels_;
};

double window(double t) {
  const double s = 1 - std::min(t, 1.0);
  return s * s;
}

double ghosts(const Grid& b, double u, double v, int channel, const FlareSettings& s) {
  if (s.ghosts <= 0) return 0;
  double sum = 0;
  for (int i = 0; i < s.ghosts; ++i) {
    const double g = kFlareGhostScales[size_t(i)] * (1 + s.chromatic * (1 - channel));
    const double su = 0.5 + (u - 0.5) / g, sv = 0.5 + (v - 0.5) / g;
    const double t = std::hypot(su - 0.5, sv - 0.5) * std::numbers::sqrt2;
    sum += b.sample_uv(su, sv, channel) / (g * g) * window(t);
  }
  return sum / s.ghosts;
}

double halo(const Grid& b, double u, double v, int channel, const FlareSettings& s) {
  const double aspect = double(b.width()) / b.height();
  const double qx = (u - 0.5) * aspect, qy = v - 0.5;  // image heights from the centre
  const double r = std::hypot(qx, qy), radius = s.halo_radius;
  if (!(r > 0)) return 0;
  const double k = 1 - radius / r;  // the source: q k, on the other side when r < R
  const double rho = std::abs(r - radius);
  return 0.5 * b.sample_uv(0.5 + qx * k / aspect, 0.5 + qy * k, channel) * (rho / r) * window(rho / radius);
}

double streaks(const Grid& b, int x, int y, int channel, const FlareSettings& s) {
  if (s.streaks <= 0) return 0;
  const double length = s.streak_length * b.width();
  const int taps = flare_streak_taps(length);
  const double step = length / taps;
  double weights = 0;
  for (int j = -taps; j <= taps; ++j) weights += std::exp(-4.0 * std::abs(j) / taps);
  double sum = 0;
  for (int line = 0; line < s.streaks; ++line) {
    const double angle = std::numbers::pi * line / s.streaks;
    const double dx = std::cos(angle) * step, dy = std::sin(angle) * step;
    for (int j = -taps; j <= taps; ++j)
      sum += std::exp(-4.0 * std::abs(j) / taps) *
             b.sample_uv((x + 0.5 + j * dx) / b.width(), (y + 0.5 + j * dy) / b.height(), channel);
  }
  return sum / (weights * s.streaks);
}

}  // namespace

uint32_t flare_grid_size(uint32_t frame, int divisor) {
  return std::max(frame / uint32_t(divisor), 1u);
}

std::array<double, 3> flare_feature_weights(const FlareSettings& s) {
  const double sum = std::max(1.0, s.ghost_weight + s.halo_weight + s.streak_weight);
  return {s.ghost_weight / sum, s.halo_weight / sum, s.streak_weight / sum};
}

int flare_streak_taps(double length_texels) {
  return std::clamp(int(std::ceil(length_texels)), 1, kFlareMaxStreakTaps);
}

FlareResult evaluate_flare(std::span<const float> rgba, uint32_t width, uint32_t height, const FlareSettings& s) {
  FlareResult result;
  const int f = s.divisor;
  Grid bright(flare_grid_size(width, f), flare_grid_size(height, f));
  result.grid_width = uint32_t(bright.width()), result.grid_height = uint32_t(bright.height());
  for (int y = 0; y < bright.height(); ++y)
    for (int x = 0; x < bright.width(); ++x) {
      Rgb sum{};
      for (int py = y * f; py < std::min(y * f + f, int(height)); ++py)
        for (int px = x * f; px < std::min(x * f + f, int(width)); ++px) {
          const Rgb c = bright_part(finite_radiance(&rgba[(size_t(py) * width + px) * 4]), s.threshold);
          for (int k = 0; k < 3; ++k) sum[k] += c[k], result.bright_energy[size_t(k)] += c[k];
        }
      for (int k = 0; k < 3; ++k) bright.at(x, y)[k] = sum[k] / (f * f);
    }

  const std::array<double, 3> w = flare_feature_weights(s);
  Grid flare(result.grid_width, result.grid_height);
  Rgb grid_bright{}, grid_flare{};
  for (int y = 0; y < flare.height(); ++y)
    for (int x = 0; x < flare.width(); ++x) {
      const double u = (x + 0.5) / flare.width(), v = (y + 0.5) / flare.height();
      for (int k = 0; k < 3; ++k) {
        // Within rgba16f's range, where the GPU keeps it.
        const double value = std::min(65504.0, w[0] * ghosts(bright, u, v, k, s) + w[1] * halo(bright, u, v, k, s) +
                                                   w[2] * streaks(bright, x, y, k, s));
        flare.at(x, y)[k] = value;
        grid_flare[k] += value;
        grid_bright[k] += bright.at(x, y)[k];
      }
    }
  for (int k = 0; k < 3; ++k) {
    result.feature_energy[size_t(k)] = grid_flare[k] * f * f;
    if (grid_flare[k] > 0) result.guard = std::min(result.guard, grid_bright[k] / grid_flare[k]);
  }

  // The image with NaN and Inf pixels as black, then the flare added over the whole blocks.
  result.rgba.assign(rgba.begin(), rgba.end());
  for (size_t p = 0; p < size_t(width) * height; ++p)
    if (!finite(&rgba[p * 4])) std::fill_n(result.rgba.begin() + std::ptrdiff_t(p * 4), 3, 0.0f);
  const int covered_w = std::min(int(width), flare.width() * f), covered_h = std::min(int(height), flare.height() * f);
  for (int py = 0; py < covered_h; ++py)
    for (int px = 0; px < covered_w; ++px)
      for (int k = 0; k < 3; ++k) {
        // Texel coordinates of the pixel's centre on the grid: (p + 0.5) / f, bilinear clamps.
        const double added = s.intensity * result.guard * flare.bilinear((px + 0.5) / f, (py + 0.5) / f, k);
        result.rgba[(size_t(py) * width + px) * 4 + size_t(k)] += float(added);
      }
  return result;
}

}  // namespace lg
