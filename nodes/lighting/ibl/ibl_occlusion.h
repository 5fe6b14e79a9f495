// lighting.ibl's occlusion formulas in double precision (nodes/lighting/ibl/shaders/
// ibl_occlusion.glsl is the same on the GPU; nodes/lighting/ibl/README.md derives them): the
// visibility cone folded into the SH cosine lobe (directional occlusion), specular occlusion from
// the cone-cone intersection, and Jimenez et al. 2016's multi-bounce fit.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <span>

namespace lg {

// Directional occlusion: irradiance through a visibility cone about `bent` (half-angle cosine
// `cone_cos` in [0, 1]) at a surface of normal `n`, the integral of L(w) V(w) (n . w) with V the
// cone's indicator, from irradiance SH coefficients (env.sh_project with convolve_cosine).
// Bands 0 to 2 exactly, from the cone's moments; the cone's part below the horizon of n (where
// it reaches past it) counts with its negative cosine, not clipped. Band 4 (orders 3 and 4)
// takes the cone's zonal factor about the bent normal as if n = bent; band 3, which irradiance
// coefficients do not carry, is lost. The result is per unit cosine-weighted visibility
// 1 - cone_cos^2 (the cone's own, as occlusion.gtao and the ray tracer define it) times
// `visibility`, at least 0: with visibility = 1 - cone_cos^2 it is the integral itself.
glm::dvec3 cone_lobe_irradiance(std::span<const glm::dvec3> irradiance_sh, const glm::dvec3& n, const glm::dvec3& bent,
                                double cone_cos, double visibility);

// The weights of irradiance coefficients 0 to 8 in cone_lobe_irradiance (visibility 1).
std::array<double, 9> cone_lobe_weights(const glm::dvec3& n, const glm::dvec3& bent, double cone_cos);
// Band 4's zonal factor of the cone-clipped cosine lobe over the cosine lobe's, per unit
// visibility: 1 + 10 c^2 - 35 c^4.
double cone_band4_ratio(double cone_cos);

// The half-angle cosine of the cone standing for the GGX lobe of perceptual `roughness` about
// the reflection: 2 (1 - alpha^2) / (2 - alpha^2), alpha = roughness^2.
double specular_cone_cosine(double roughness);

// The solid angle shared by two caps (half-angle cosines cos1, cos2 >= 0) with axes at cosine
// cos_d; the closed form (Gauss-Bonnet on the lens), its angles by atan2 over one shared sine.
double cap_intersection(double cos1, double cos2, double cos_d);

// The visible fraction of the specular lobe's cone: inside the visibility cone (axis `bent`,
// `cone_cos`) over inside the hemisphere of `n` (at least 5% of the lobe), clamped to [0, 1];
// unit vectors.
double specular_occlusion_from_cone(const glm::dvec3& n, const glm::dvec3& r, const glm::dvec3& bent, double cone_cos,
                                    double roughness);

// Jimenez et al. 2016's cubic in visibility and albedo, clamped to [visibility, 1].
double multi_bounce_occlusion(double visibility, double albedo);
// The cubic alone, for tests of the fit.
double multi_bounce_cubic(double visibility, double albedo);

}  // namespace lg
