// env.sh_project's reference: the projection onto real SH in double precision, summing over
// every texel of the cube (brute force: the radiance of each texel times the integral of Y_lm
// over the texel by 4x4 Gauss points), with the same treatment of non-finite texels (counted, 0).
#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "nodes/env/common/cube_map.h"

namespace lg {

struct ShReference {
  std::vector<glm::dvec3> coefficients;  // sh_count(order), scaled by band_factors
  int non_finite = 0;
};

ShReference project_sh_reference(const CubeImage& env, int order, std::span<const double> band_factors);

// The SH reconstruction sum_k c_k Y_k(direction).
glm::dvec3 evaluate_sh(std::span<const glm::dvec3> coefficients, const glm::dvec3& direction);

}  // namespace lg
