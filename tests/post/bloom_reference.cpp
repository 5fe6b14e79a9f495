#include "tests/post/bloom_reference.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace lg::test {
namespace {

// A 1D kernel on the lattice of half pixels: key 2 x offset.
using Lattice = std::map<int, double>;

Lattice convolve(const Lattice& a, const Lattice& b) {
  Lattice out;
  for (const auto& [i, x] : a)
    for (const auto& [j, y] : b) out[i + j] += x * y;
  return out;
}

double tent(double t) {
  return std::max(0.0, 1.0 - std::abs(t));
}

// Level l from the level above it (texels `spacing` pixels apart): bilinear taps one texel either
// side of the new centre, which falls between texels, so 4 texels at +-0.5 and +-1.5 spacings.
Lattice box_down(int spacing) {
  Lattice k;
  for (int t : {-3, -1, 1, 3}) k[t * spacing] += 0.25;
  return k;
}

// The weight of a texel of the coarser level (texels `coarse` pixels apart) in a texel of the
// finer one, by their centres' offset v = fine - coarse, which is an odd multiple of coarse / 4:
// the [1 2 1] / 4 taps at v + k coarse, each bilinear between the coarse texels.
Lattice tent_up(int coarse) {
  Lattice k;
  for (int odd = -15; odd <= 15; odd += 2) {
    const double v = odd * coarse / 4.0;
    double w = 0;
    for (int t = -1; t <= 1; ++t) w += (t == 0 ? 0.5 : 0.25) * tent((v + t * coarse) / coarse);
    if (w > 0) k[int(2 * v)] += w;
  }
  return k;
}

}  // namespace

std::vector<double> bloom_level_kernel(uint32_t level) {
  if (level > 12) throw std::invalid_argument("bloom kernel: level " + std::to_string(level) + " is past 12");
  Lattice down = box_down(1);
  for (uint32_t l = 1; l <= level; ++l) down = convolve(down, box_down(1 << l));
  // The composite's bilinear from level 0 (texels 2 pixels apart, offsets +-0.5 and +-1.5) ...
  Lattice up;
  for (int odd = -3; odd <= 3; odd += 2) up[odd] = tent(odd / 4.0);
  // ... after each level's tent into the one above it.
  for (uint32_t l = 1; l <= level; ++l) up = convolve(up, tent_up(2 << l));
  const Lattice k = convolve(up, down);
  const int radius = std::max(std::abs(k.begin()->first), std::abs(k.rbegin()->first)) / 2;
  std::vector<double> kernel(2 * size_t(radius) + 1, 0.0);
  const double s = double(2u << level);
  for (const auto& [twice, w] : k) {
    if (twice % 2 != 0) throw std::logic_error("bloom kernel: a weight off the pixel lattice");
    kernel[size_t(twice / 2 + radius)] += w / s;
  }
  return kernel;
}

HostImage convolve_separable(const HostImage& image, const std::vector<double>& kernel) {
  const int w = int(image.width), h = int(image.height), r = int(kernel.size() / 2);
  std::vector<double> rows(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int i = -r; i <= r; ++i)
          sum += kernel[i + r] * image.rgba[(size_t(y) * w + std::clamp(x + i, 0, w - 1)) * 4 + c];
        rows[(size_t(y) * w + x) * 3 + c] = sum;
      }
  HostImage out = image;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int i = -r; i <= r; ++i)
          sum += kernel[i + r] * rows[(size_t(std::clamp(y + i, 0, h - 1)) * w + x) * 3 + c];
        out.rgba[(size_t(y) * w + x) * 4 + c] = float(sum);
      }
  return out;
}

HostImage bloom_reference(const HostImage& image, uint32_t levels) {
  HostImage sum = image;
  std::fill(sum.rgba.begin(), sum.rgba.end(), 0.0f);
  for (uint32_t l = 0; l < levels; ++l) {
    const HostImage level = convolve_separable(image, bloom_level_kernel(l));
    for (size_t k = 0; k < sum.rgba.size(); ++k)
      if (k % 4 != 3) sum.rgba[k] += level.rgba[k] / float(levels);
  }
  return sum;
}

}  // namespace lg::test
