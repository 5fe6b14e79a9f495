// env.specular_prefilter's reference in double precision: the split-sum prefiltered radiance
// for normal n (N = V = R), integrated over every texel of the environment (brute force):
// sum L D(h) (n.l) dw / sum D(h) (n.l) dw over texels with n.l > 0, h = normalize(n + l).
// Roughness 0 has no lobe to integrate: callers compare it to the environment itself.
#pragma once

#include <glm/vec3.hpp>

#include "nodes/env/common/cube_map.h"

namespace lg {

glm::dvec3 prefiltered_reference(const CubeImage& env, const glm::dvec3& n, double roughness);

}  // namespace lg
