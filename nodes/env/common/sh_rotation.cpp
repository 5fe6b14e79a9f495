// sh_rotation(): per band, the least-squares fit of the turned basis at a fixed spherical
// Fibonacci set of directions (sh_rotation.h).
#include "nodes/env/common/sh_rotation.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nodes/env/common/sh_basis.h"

namespace lg {
namespace {

// 64 directions: well spread, so that every band up to 4 (9 functions) is fitted with a
// well-conditioned normal matrix.
constexpr int kDirections = 64;

std::array<glm::dvec3, kDirections> fit_directions() {
  std::array<glm::dvec3, kDirections> d;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kDirections; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / kDirections, r = std::sqrt(1.0 - z * z);
    d[i] = {r * std::cos(golden * i), r * std::sin(golden * i), z};
  }
  return d;
}

// Band l of the basis at each direction: kDirections rows of 2l + 1.
std::vector<double> band_values(int l, std::span<const glm::dvec3> directions) {
  const int n = 2 * l + 1;
  std::vector<double> values(directions.size() * n), y(sh_count(l));
  for (size_t i = 0; i < directions.size(); ++i) {
    sh_evaluate(l, directions[i], y);
    for (int m = 0; m < n; ++m) values[i * n + m] = y[l * l + m];
  }
  return values;
}

// (A^T A)^-1 A^T for A = band_values(l, fit directions): n x kDirections, row-major, by
// Gauss-Jordan elimination with partial pivoting on the n x n normal matrix.
std::vector<double> band_fit(int l) {
  const int n = 2 * l + 1;
  const auto directions = fit_directions();
  const std::vector<double> a = band_values(l, directions);
  std::vector<double> normal(n * n, 0.0), inverse(n * n, 0.0);
  for (int r = 0; r < n; ++r) {
    inverse[r * n + r] = 1.0;
    for (int c = 0; c < n; ++c)
      for (int i = 0; i < kDirections; ++i) normal[r * n + c] += a[i * n + r] * a[i * n + c];
  }
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r)
      if (std::abs(normal[r * n + col]) > std::abs(normal[pivot * n + col])) pivot = r;
    for (int c = 0; c < n; ++c)
      std::swap(normal[col * n + c], normal[pivot * n + c]), std::swap(inverse[col * n + c], inverse[pivot * n + c]);
    const double scale = 1.0 / normal[col * n + col];
    for (int c = 0; c < n; ++c) normal[col * n + c] *= scale, inverse[col * n + c] *= scale;
    for (int r = 0; r < n; ++r) {
      if (r == col) continue;
      const double f = normal[r * n + col];
      for (int c = 0; c < n; ++c)
        normal[r * n + c] -= f * normal[col * n + c], inverse[r * n + c] -= f * inverse[col * n + c];
    }
  }
  std::vector<double> fit(n * kDirections, 0.0);
  for (int r = 0; r < n; ++r)
    for (int i = 0; i < kDirections; ++i)
      for (int c = 0; c < n; ++c) fit[r * kDirections + i] += inverse[r * n + c] * a[i * n + c];
  return fit;
}

const std::vector<double>& cached_band_fit(int l) {
  static const std::array<std::vector<double>, kMaxShOrder + 1> fits = [] {
    std::array<std::vector<double>, kMaxShOrder + 1> f;
    for (int band = 0; band <= kMaxShOrder; ++band) f[band] = band_fit(band);
    return f;
  }();
  return fits[l];
}

}  // namespace

ShRotation sh_rotation(int order, const glm::dmat3& rotation) {
  if (order < 0 || order > kMaxShOrder) throw std::invalid_argument("SH rotation: order must be 0 to 4");
  ShRotation out{order, std::vector<double>(sh_rotation_offset(order + 1), 0.0)};
  const auto directions = fit_directions();
  std::array<glm::dvec3, kDirections> turned;
  for (int i = 0; i < kDirections; ++i) turned[i] = glm::transpose(rotation) * directions[i];
  for (int l = 0; l <= order; ++l) {
    const int n = 2 * l + 1;
    const std::vector<double>& fit = cached_band_fit(l);
    const std::vector<double> b = band_values(l, turned);
    double* block = out.blocks.data() + sh_rotation_offset(l);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        for (int i = 0; i < kDirections; ++i) block[r * n + c] += fit[r * kDirections + i] * b[i * n + c];
  }
  return out;
}

void ShRotation::apply(std::span<const glm::dvec3> in, std::span<glm::dvec3> out) const {
  for (int l = 0; l <= order; ++l) {
    const int n = 2 * l + 1;
    const double* block = blocks.data() + sh_rotation_offset(l);
    for (int r = 0; r < n; ++r) {
      glm::dvec3 sum(0.0);
      for (int c = 0; c < n; ++c) sum += block[r * n + c] * in[l * l + c];
      out[l * l + r] = sum;
    }
  }
}

}  // namespace lg
