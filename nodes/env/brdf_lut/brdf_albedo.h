// The GGX lobe's directional albedo for lights that have no DFG table at hand (lighting.deferred's
// direct and area lights, the path tracer): the split-sum scale A and bias B (the integral of
// f_spec (n.l) = F0 A + B, dfg_reference.h) tabulated on a 32 x 32 grid of (n.v, roughness) by
// make_brdf_albedo_table.cpp into brdf_albedo_table.inc, which shaders/brdf_albedo.glsl reads
// from a uniform block (brdf_albedo_texels); and the energy sharing both lighting paths derive
// from (A, B), whichever table gave them.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace lg {

// Texel (i, j) at n.v = (i / (size - 1))^4 (floored at 1e-4, as the BRDF clamps it) and
// perceptual roughness j / (size - 1) (alpha = roughness^2 floored at 1e-3, likewise); (A, B)
// interleaved, rows of n.v. The fourth root puts texels where the albedo of a near-mirror turns,
// at grazing views (n.v near alpha): along n.v itself, the white albedo between the first two
// texels was 5% off, along its square root 2.5%.
constexpr int kBrdfAlbedoSize = 32;
extern const float kBrdfAlbedoTable[2 * kBrdfAlbedoSize * kBrdfAlbedoSize];

// The table's value at (n.v, roughness) by dfg_reference, with the BRDF's floors applied.
glm::dvec2 brdf_albedo_reference(double n_dot_v, double roughness, int steps = 256);

// Where n.v lies along the table's first axis, in texels.
double brdf_albedo_column(double n_dot_v);

// The table as shaders read it from a uniform block (brdf_albedo.glsl): two texels a vec4.
std::array<glm::vec4, kBrdfAlbedoSize * kBrdfAlbedoSize / 2> brdf_albedo_texels();

// (A, B) bilinearly between texels, as brdf_albedo.glsl does in float.
glm::dvec2 brdf_albedo_lookup(double n_dot_v, double roughness);

// E = A + B, the lobe's white albedo (Fresnel 1), floored where it divides.
double white_albedo(glm::dvec2 scale_bias);

// Multiple scattering returns what single scattering loses (1 - E, E = A + B the white albedo)
// in proportion to F0: the single-scattering specular times 1 + F0 (1 / E - 1) (Fdez-Aguera
// 2019; Kulla and Conty 2017 with Fms's lobe folded into the single one's shape).
glm::dvec3 specular_energy_scale(glm::dvec3 f0, glm::dvec2 scale_bias);

// The specular lobe's albedo with that compensation, (F0 A + B) (1 + F0 (1 / E - 1)): what the
// diffuse lobe under it does not get. The diffuse is weighted by 1 minus this at the view, so a
// white dielectric under a constant environment reflects exactly that environment.
glm::dvec3 specular_albedo(glm::dvec3 f0, glm::dvec2 scale_bias);

}  // namespace lg
