#include "editor/env_sh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lg {

std::array<double, 9> sh_l2_basis(const Vec3d& d) {
  const double x = d[0], y = d[1], z = d[2];
  // Normalisation constants sqrt((2l+1)/(4 pi) (l-|m|)!/(l+|m|)!), with sqrt(2) for m != 0.
  const double pi = std::numbers::pi;
  const double k0 = 0.5 * std::sqrt(1 / pi);
  const double k1 = std::sqrt(3 / (4 * pi));
  const double k2 = 0.5 * std::sqrt(15 / pi);
  const double k20 = 0.25 * std::sqrt(5 / pi);
  const double k22 = 0.25 * std::sqrt(15 / pi);
  return {k0, k1 * y, k1 * z, k1 * x, k2 * x * y, k2 * y * z, k20 * (3 * z * z - 1), k2 * x * z, k22 * (x * x - y * y)};
}

Vec3d equirect_direction(double u, double v) {
  const double theta = std::numbers::pi * v, phi = 2 * std::numbers::pi * u;
  return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

std::array<double, 2> equirect_uv(const Vec3d& d) {
  double phi = std::atan2(d[2], d[0]);
  if (phi < 0) phi += 2 * std::numbers::pi;
  const double u = phi / (2 * std::numbers::pi);
  return {u >= 1 ? 0 : u, std::acos(std::clamp(d[1], -1.0, 1.0)) / std::numbers::pi};
}

double equirect_texel_solid_angle(uint32_t row, uint32_t width, uint32_t height) {
  const double t0 = std::numbers::pi * row / height, t1 = std::numbers::pi * (row + 1) / height;
  return 2 * std::numbers::pi / width * (std::cos(t0) - std::cos(t1));
}

ShL2 project_equirect_sh_l2(uint32_t width, uint32_t height, std::span<const float> rgba) {
  ShL2 sh;
  for (uint32_t row = 0; row < height; ++row) {
    const double weight = equirect_texel_solid_angle(row, width, height);
    for (uint32_t col = 0; col < width; ++col) {
      const float* texel = &rgba[(size_t(row) * width + col) * 4];
      if (!std::isfinite(texel[0]) || !std::isfinite(texel[1]) || !std::isfinite(texel[2])) continue;
      // The texel centre stands for the texel; the weight is the texel's exact area.
      const auto basis = sh_l2_basis(equirect_direction((col + 0.5) / width, (row + 0.5) / height));
      for (int k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) sh.rgb[k][c] += texel[c] * basis[k] * weight;
    }
  }
  return sh;
}

Vec3d evaluate_sh_l2(const ShL2& sh, const Vec3d& d) {
  const auto basis = sh_l2_basis(d);
  Vec3d out{};
  for (int k = 0; k < 9; ++k)
    for (int c = 0; c < 3; ++c) out[c] += sh.rgb[k][c] * basis[k];
  return out;
}

}  // namespace lg
