// Rotating a function given by its real SH coefficients (sh_basis.h) up to band 4: a rotation
// acts on each band alone, as a (2l + 1) x (2l + 1) matrix. The matrices come from point
// evaluation: band l of the turned function f'(w) = f(R^T w) takes at fixed directions d_i the
// values of the band's basis at R^T d_i, and since a band is closed under rotation, the least-
// squares fit of those values in the basis at d_i is exact (to rounding). Used to turn an
// environment's SH every frame instead of baking precomputed transfer again (gi.prt).
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace lg {

struct ShRotation {
  int order = 0;
  // Band l's matrix, row-major, at offset sum_{j < l} (2j + 1)^2: coefficient l(l+1)+m of the
  // turned function is sum_m' M_l[m][m'] times coefficient l(l+1)+m' of the original.
  std::vector<double> blocks;

  // out = the coefficients of the turned function; in and out hold sh_count(order) each.
  void apply(std::span<const glm::dvec3> in, std::span<glm::dvec3> out) const;
};

// The floats one ShRotation of band 4 holds: 1 + 9 + 25 + 49 + 81.
inline constexpr int kShRotationFloats = 165;
// Where band l's matrix starts in ShRotation::blocks.
constexpr int sh_rotation_offset(int l) {
  int offset = 0;
  for (int j = 0; j < l; ++j) offset += (2 * j + 1) * (2 * j + 1);
  return offset;
}

// The matrices that turn functions of bands 0..order (at most 4) by `rotation` (orthonormal,
// determinant 1): f'(w) = f(rotation^T w).
ShRotation sh_rotation(int order, const glm::dmat3& rotation);

}  // namespace lg
