// env.irradiance's reference in double precision: irradiance / pi at normal n, the cosine-
// weighted sum over every texel of the environment (brute force) with exact solid angles,
// non-finite texels counted as 0.
#pragma once

#include <glm/vec3.hpp>

#include "nodes/env/common/cube_map.h"

namespace lg {

glm::dvec3 irradiance_over_pi_reference(const CubeImage& env, const glm::dvec3& n);

}  // namespace lg
