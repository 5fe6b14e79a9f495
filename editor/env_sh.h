// Order-2 (L2, nine coefficients) real spherical harmonics of equirectangular environments, on
// the CPU in double precision: projection with the exact solid angle of every texel, and
// reconstruction. The inspector shows an environment beside its SH to judge what L2 keeps.
//
// Directions: +Y is up and the top row of the image; the polar angle theta runs from +Y down,
// the azimuth phi = 2 pi u from +X towards +Z: d = (sin theta cos phi, cos theta, sin theta sin phi).
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace lg {

using Vec3d = std::array<double, 3>;

struct ShL2 {
  std::array<Vec3d, 9> rgb{};  // coefficient k for red, green, blue
};

// The nine real SH basis functions at a unit direction, in the usual order
// (l, m) = (0,0), (1,-1), (1,0), (1,1), (2,-2), (2,-1), (2,0), (2,1), (2,2).
std::array<double, 9> sh_l2_basis(const Vec3d& d);

// The direction through the point (u, v) of the image, u and v in [0, 1], v = 0 the top row.
Vec3d equirect_direction(double u, double v);
// (u, v) of a unit direction: the inverse of equirect_direction, u in [0, 1), v in [0, 1].
std::array<double, 2> equirect_uv(const Vec3d& d);

// The solid angle a texel of row `row` covers: (2 pi / width) (cos theta0 - cos theta1). A whole
// image sums to 4 pi exactly, whatever its size.
double equirect_texel_solid_angle(uint32_t row, uint32_t width, uint32_t height);

// Projects an RGBA float image (rows top to bottom) onto L2 SH, each texel weighted by its solid
// angle. Non-finite texels are skipped, so one NaN does not poison the nine coefficients.
ShL2 project_equirect_sh_l2(uint32_t width, uint32_t height, std::span<const float> rgba);

Vec3d evaluate_sh_l2(const ShL2& sh, const Vec3d& d);

}  // namespace lg
