// Fits a linearly transformed cosine to brdf.glsl's GGX lobe at one view and roughness, in double
// precision (Heitz et al. 2016, section 4): lumagraph-ltc-fit writes the table of ltc_table.h with
// it, and a test re-fits entries against the committed table.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

namespace lg {

struct LtcFit {
  glm::dmat3 m;        // the transform M of the cosine lobe (its inverse is what shaders use)
  glm::dvec4 entry;    // M^-1 scaled to a middle element of 1, as the table stores it
  double error = 0.0;      // the first stage's objective (below)
  double cap_error = 0.0;  // the second stage's: mean squared error of the caps' integrals
  int evaluations = 0;
};

// The lobe f(v, l) (n.l) with Fresnel 1, normalised to integrate to 1, at view n.v and perceptual
// roughness (alpha floored as ltc_alpha does). F is the frame whose z is the lobe's mean direction
// (computed), x in the plane of n and v, and
//   M = F [[a, 0, b], [0, c, 0], [d, 0, 1]],
// the four values fitted from a = c = alpha, b = d = 0 by Nelder-Mead with two restarts (Heitz
// et al. fit three, d = 0; the fourth brought the specular's relative RMS on 600 of the
// benchmark's points from 0.22 to 0.16). The objective is the
// integral of |lobe - LTC|, estimated on a fixed 32 x 32 stratified grid drawn from each (the
// lobe by sampling GGX's normals, the LTC by sampling its cosine) and combined by the balance
// heuristic. Heitz et al. fit |lobe - LTC|^3, which favours the peak; the first power weighs the
// lobe's tails, where most shading points see a light, as much: on 120 random lights and views
// (roughness 0.25 to 1) the specular's relative RMS fell from 24% (cube) and 19% (square) to
// 14%; a power of 1.5 gave 15%, of 0.5 92%. That is the first stage. The second starts there and
// fits the integrals the area lights use: the LTC's integral over about 180 cones of directions
// (half-angles 3 to 40 degrees over the hemisphere and across its horizon, and the lobe's width
// around its peak; clipped to the horizon as the shaders clip) against the lobe's, in least
// squares. On the benchmark's 1200 points it took LTC's relative RMS from 0.20 to 0.16, across
// the horizon for rectangles from 0.44 to 0.34 (README.md). Deterministic: the same inputs give
// the same fit.
LtcFit fit_ltc(double n_dot_v, double roughness);

// The density of the LTC with inverse transform m_inv at unit direction l (zero below its
// horizon): cos(theta_o) / pi |det M^-1| / |M^-1 l|^3 with l_o = M^-1 l / |M^-1 l|.
double ltc_density(const glm::dmat3& m_inv, glm::dvec3 l);

}  // namespace lg
