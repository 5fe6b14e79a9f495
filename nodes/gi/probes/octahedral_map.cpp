#include "nodes/gi/probes/octahedral_map.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace lg {
namespace {

double sign_not_zero(double v) {
  return v >= 0.0 ? 1.0 : -1.0;
}

}  // namespace

glm::dvec2 octahedral_encode(glm::dvec3 d) {
  const double l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  glm::dvec2 p(d.x / l1, d.y / l1);
  if (d.z < 0.0) p = glm::dvec2((1.0 - std::abs(p.y)) * sign_not_zero(p.x), (1.0 - std::abs(p.x)) * sign_not_zero(p.y));
  return p * 0.5 + 0.5;
}

glm::dvec3 octahedral_decode(glm::dvec2 uv) {
  const glm::dvec2 f = uv * 2.0 - 1.0;
  glm::dvec3 n(f.x, f.y, 1.0 - std::abs(f.x) - std::abs(f.y));
  const double t = std::max(-n.z, 0.0);
  n.x += n.x >= 0.0 ? -t : t;
  n.y += n.y >= 0.0 ? -t : t;
  return glm::normalize(n);
}

glm::ivec2 octahedral_wrap(int i, int j, int k) {
  const bool out_i = i < 0 || i >= k, out_j = j < 0 || j >= k;
  if (out_i && out_j) return {i < 0 ? k - 1 : 0, j < 0 ? k - 1 : 0};  // past a corner: the opposite one
  if (out_i) return {i < 0 ? 0 : k - 1, k - 1 - j};
  if (out_j) return {k - 1 - i, j < 0 ? 0 : k - 1};
  return {i, j};
}

OctahedralTaps octahedral_taps(glm::dvec3 direction, int k) {
  const glm::dvec2 p = octahedral_encode(direction) * double(k) - 0.5;
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const double tx = p.x - fx, ty = p.y - fy;
  OctahedralTaps taps;
  for (int n = 0; n < 4; ++n) {
    const int dx = n & 1, dy = n >> 1;
    taps.texel[n] = octahedral_wrap(int(fx) + dx, int(fy) + dy, k);
    taps.weight[n] = (dx ? tx : 1.0 - tx) * (dy ? ty : 1.0 - ty);
  }
  return taps;
}

}  // namespace lg
