// Stratified cosine-weighted hemisphere samples from hashed jitter (cosine_sampling.h).
#include "nodes/raytrace/cosine_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lg {

uint64_t mix_bits(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

double hashed_uniform(uint64_t seed, uint64_t index, uint32_t dimension) {
  const uint64_t h = mix_bits(mix_bits(mix_bits(seed) ^ index) + dimension);
  return double(h >> 11) * 0x1.0p-53;  // 53 random bits: exactly representable, below 1
}

glm::dvec2 stratified_point(uint32_t index, uint32_t count, uint64_t seed) {
  const uint32_t rows = std::max(1u, uint32_t(std::sqrt(double(count))));
  const uint32_t base = count / rows, wide_rows = count % rows;  // the first wide_rows have base + 1
  const uint32_t in_wide_rows = wide_rows * (base + 1);
  uint32_t row, column, cells;
  if (index < in_wide_rows) {
    row = index / (base + 1), column = index % (base + 1), cells = base + 1;
  } else {
    row = wide_rows + (index - in_wide_rows) / base, column = (index - in_wide_rows) % base, cells = base;
  }
  const uint32_t row_start = row * base + std::min(row, wide_rows);  // samples in the rows below
  const double x = (column + hashed_uniform(seed, index, 0)) / cells;
  const double y = (row_start + cells * hashed_uniform(seed, index, 1)) / count;
  return {x, std::min(y, std::nextafter(1.0, 0.0))};
}

glm::dvec2 concentric_disk(glm::dvec2 u) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};
  constexpr double quarter_pi = std::numbers::pi / 4.0;
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) {
    r = a, phi = quarter_pi * (b / a);
  } else {
    r = b, phi = 2.0 * quarter_pi - quarter_pi * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

glm::dvec3 cosine_hemisphere(glm::dvec2 u) {
  const glm::dvec2 d = concentric_disk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}

Frame make_frame(glm::dvec3 n) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  return {{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
}

}  // namespace lg
