// lighting.ibl's occlusion formulas in double precision (nodes/lighting/ibl/shaders/
// ibl_occlusion.glsl is the same on the GPU; nodes/lighting/ibl/README.md derives them): the
// visibility cone folded into the SH cosine lobe (directional occlusion), specular occlusion from
// the cone-cone intersection, and Jimenez et al. 2016's multi-bounce fit.
#pragma once

#include <glm/vec3.hpp>
#include <span>

namespace lg {

// Band l's factor of the cosine lobe clipped to a cone about its own axis (half-angle cosine
// `cone_cos` in [0, 1]) over the plain cosine lobe's, per unit cosine-weighted visibility
// 1 - cone_cos^2. 0 for band 3, which irradiance coefficients do not carry.
double cone_lobe_band_ratio(int l, double cone_cos);

// Irradiance through a visibility cone from irradiance SH coefficients (env.sh_project with
// convolve_cosine, orders up to 4): `visibility` * sum_k ratio_l(cone_cos) E_k Y_k(bent), at
// least 0. With visibility = 1 - cone_cos^2 it is the integral of L V max(0, bent . w) with V the
// cone's indicator (exactly, for radiance without band 3); lighting.ibl passes its AO there.
glm::dvec3 cone_lobe_irradiance(std::span<const glm::dvec3> irradiance_sh, const glm::dvec3& bent, double cone_cos,
                                double visibility);

// The half-angle cosine of the cone standing for the GGX lobe of perceptual `roughness` about
// the reflection: 2 (1 - alpha^2) / (2 - alpha^2), alpha = roughness^2.
double specular_cone_cosine(double roughness);

// The solid angle shared by two caps (half-angle cosines cos1, cos2 >= 0) with axes at cosine
// cos_d; the closed form (Gauss-Bonnet on the lens).
double cap_intersection(double cos1, double cos2, double cos_d);

// The visible fraction of the specular lobe's cone: inside the visibility cone (axis `bent`,
// `cone_cos`) over inside the hemisphere of `n`, clamped to [0, 1]; unit vectors.
double specular_occlusion_from_cone(const glm::dvec3& n, const glm::dvec3& r, const glm::dvec3& bent, double cone_cos,
                                    double roughness);

// Jimenez et al. 2016's cubic in visibility and albedo, clamped to [visibility, 1].
double multi_bounce_occlusion(double visibility, double albedo);
// The cubic alone, for tests of the fit.
double multi_bounce_cubic(double visibility, double albedo);

}  // namespace lg
