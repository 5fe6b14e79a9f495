// gi.lpv's propagation on the CPU in double precision: the model its shaders implement
// (shaders/lpv_common.glsl, lpv_propagate.comp), for tests. Kaplanyan and Dachsbacher 2010: each
// cell holds the radiant intensity of the light in it as SH L1 per colour channel; a step moves
// every cell's light to its six face neighbours. For a neighbour along d, the source's intensity
// (read as sh_l1_lobe) towards each of the five faces of the neighbour's cell that do not face
// back (the far face, seen under 0.4006696846 sr from the source's centre, and four side faces,
// 0.4234313544 sr each) times that solid angle is the flux through the face, re-emitted from the
// neighbour's centre as a clamped-cosine lobe about the direction it crossed the face in. The six neighbours' faces together cover
// the whole sphere (6 x (0.40067 + 4 x 0.42343) = 4 pi), so an isotropic source keeps its power.
// Light leaving the grid is lost.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <vector>

namespace lg {

using ShL1 = std::array<double, 4>;  // coefficients of Y00, Y1-1 (y), Y10 (z), Y11 (x)

ShL1 sh_l1_basis(glm::dvec3 direction);  // `direction` unit
// The SH L1 projection of max(0, n . w): pi Y00 and 2 pi / 3 Y1m(n). Times phi / pi it is a
// Lambertian emitter of power phi about n; dotted with radiance it is the irradiance at normal n.
ShL1 sh_l1_cosine_lobe(glm::dvec3 n);
double sh_l1_eval(const ShL1& sh, glm::dvec3 direction);
// Power of an intensity distribution: its integral over the sphere, sqrt(4 pi) times Y00's coefficient.
double sh_l1_power(const ShL1& sh);

// The coefficients read as the non-negative distribution with the same L1 projection: an
// isotropic part a plus a clamped-cosine lobe b max(0, d . w), the lobe as strong as the
// coefficients allow (a = 0 for a pure cosine lobe, b = 0 for an isotropic source). The series
// itself, 1/4 + 1/2 cos for a cosine lobe, sends a third of a surface's peak intensity along the
// surface and lets a lit floor light itself; this reading sends none (docs/lpv.md).
struct ShLobe {
  double a = 0, b = 0;
  glm::dvec3 d{0.0};
};
ShLobe sh_l1_lobe(const ShL1& sh);
double sh_lobe_eval(const ShLobe& lobe, glm::dvec3 direction);
// The irradiance at a surface of normal n from radiance distributed so, the light travelling
// along w with w . n < 0: pi a + b 2/3 ((pi - t) cos t + sin t), t the angle between d and -n.
double sh_lobe_irradiance(const ShLobe& lobe, glm::dvec3 n);

struct LpvVolume {
  glm::ivec3 counts{1};
  std::vector<std::array<ShL1, 3>> light;  // per cell, per channel: radiant intensity, W/sr
  // Per cell: how much of the light crossing the cell is blocked, by direction of travel w: the
  // coefficients read as a lobe (sh_l1_lobe) at -w (surfaces facing the light block it), clamped
  // to [0, 1].
  std::vector<ShL1> occlusion;

  explicit LpvVolume(glm::ivec3 counts);
  size_t index(glm::ivec3 cell) const;
  bool inside(glm::ivec3 cell) const;
};

// How light moves into a cell from its neighbour on the side -direction (kLpvDirections[d]):
// through five faces, each with the SH basis at the direction from the neighbour's centre to the
// face's centre (where the neighbour's intensity is read, and the occlusion at its opposite) and
// the lobe the flux is re-emitted with (solid angle / pi x sh_l1_cosine_lobe(that direction):
// the light keeps going the way it crossed the face; the method as published re-emits about the
// face's normal, which turns four fifths of a beam sideways every step). The
// GPU reads the same table (lpv_kernel.cpp uploads it).
struct LpvFace {
  ShL1 towards_basis;
  glm::dvec3 towards;
  ShL1 emitted_lobe;
  double solid_angle;
};
inline constexpr int kLpvFacesPerDirection = 5;
const std::array<glm::ivec3, 6>& lpv_directions();
const std::array<std::array<LpvFace, kLpvFacesPerDirection>, 6>& lpv_faces();

// What a step sends out of a cell from a unit lobe max(0, d . w) (d unit): its value towards
// every face of lpv_faces() times the face's solid angle. The lobe's power is pi; this falls
// short by up to 15% (d along an axis) and exceeds it by up to 5% (diagonals), so a step scales
// a source's lobe part by pi / this and keeps its power (the shaders' lpv_outflow).
double sh_lobe_sampled_outflow(glm::dvec3 d);

// The fraction of light travelling along `direction` that gets from a cell to its neighbour
// through the occlusion of both (the mean of their lobes, sh_l1_lobe, at -direction, clamped to
// [0, 1]): a surface blocks light that travels into it, not light that runs along it (the L1
// series would block a quarter of that).
double lpv_transmittance(const ShL1& source, const ShL1& destination, glm::dvec3 direction);

// One step: the light of `in` moved to its face neighbours (only that: the caller adds the steps
// up); `occlude` applies the occlusion volume.
LpvVolume propagate_step(const LpvVolume& in, bool occlude);

}  // namespace lg
