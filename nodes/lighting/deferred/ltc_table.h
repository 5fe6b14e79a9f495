// The linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light
// Shading with Linearly Transformed Cosines") that stand in for the GGX lobe of brdf.glsl in the
// area lights' specular: a 32 x 32 table over (n.v, roughness) of the inverse transform, fitted by
// lumagraph-ltc-fit (make_ltc_table.cpp, ltc_fit.h) into ltc_table.inc. The lobe's magnitude is
// not in it: that is the directional albedo the BRDF's albedo table already holds
// (nodes/env/brdf_lut/brdf_albedo.h), with the Fresnel and multiple-scattering terms the other
// lights use.
#pragma once

#include <array>
#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

namespace lg {

// Entry (i, j): n.v = 1 - (i / (size - 1))^2 (floored at 1e-4, as the BRDF clamps it; the square
// puts entries where the lobe changes fastest, toward grazing views) and perceptual roughness
// j / (size - 1) (alpha = roughness^2 floored at 1e-3, as brdf.glsl's). Each holds the inverse
// transform M^-1 scaled so that its middle element is 1, as (m00, m02, m20, m22) (row, column):
// M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the frame of the normal (z) and the view
// (in the xz plane, x >= 0). Rows of n.v.
constexpr int kLtcSize = 32;
extern const float kLtcTable[4 * kLtcSize * kLtcSize];

double ltc_grid_n_dot_v(int i);
double ltc_grid_roughness(int j);
// As brdf.glsl floors it.
double ltc_alpha(double roughness);

// The entry's four values bilinearly between entries, as area_light_ltc.glsl reads them.
glm::vec4 ltc_lookup(float n_dot_v, float roughness);

// M^-1 from the four values.
glm::mat3 ltc_inverse(glm::vec4 entry);

// The table as the shaders read it from a storage buffer: one entry a vec4.
std::array<glm::vec4, kLtcSize * kLtcSize> ltc_table_texels();

}  // namespace lg
