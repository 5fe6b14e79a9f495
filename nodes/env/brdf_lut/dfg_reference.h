// env.brdf_lut's reference in double precision: the split-sum scale A and bias B of GGX with
// height-correlated Smith visibility, integral of f_spec (n.l) = F0 A + B with Schlick's
// Fresnel (nodes/env/brdf_lut/shaders/dfg.comp states the table's layout).
#pragma once

#include <glm/vec2.hpp>

namespace lg {

// The specular BRDF both tables describe, without Fresnel: GGX D(h) times the height-correlated
// Smith visibility G2 / (4 n.l n.v) (brdf.glsl's ggx_distribution x smith_visibility).
double ggx_specular_brdf(double n_dot_v, double n_dot_l, double n_dot_h, double alpha);

// By a dense midpoint rule over the visible-normal variables of Heitz (2018) (in which the
// integrand is G2 / G1(v) F, smooth and bounded), `steps` x 4 `steps` points: any roughness.
glm::dvec2 dfg_reference(double n_dot_v, double roughness, int steps = 256);

// By a dense midpoint rule over the light direction's (theta, phi): independent of the
// half-vector mapping, but needs roughness well above 0 to resolve the lobe.
glm::dvec2 dfg_reference_over_light(double n_dot_v, double roughness, int steps = 2048);

}  // namespace lg
