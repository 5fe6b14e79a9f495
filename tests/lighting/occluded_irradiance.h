// What the tests of lighting.ibl's occlusion against ray tracing share: the ray-traced
// reference irradiance at a surface point (the integral of L(w) V(w) max(0, n . w) over every
// texel of an environment cube, one Embree visibility ray per texel), luminance, and the mean
// and 95th percentile of per-point errors.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "nodes/env/common/cube_map.h"
#include "nodes/raytrace/ray_scene.h"

namespace lg::test {

double luminance(const glm::dvec3& c);

struct OccludedIrradiance {
  glm::dvec3 reference{0.0};  // through the scene's occluders
  glm::dvec3 open{0.0};       // with nothing in the way
};

// At `position` with geometric normal `geometric` (the rays leave from just above that
// surface) and shading normal `shading` (the cosine's).
OccludedIrradiance occluded_irradiance(const RayScene& scene, const CubeImage& env, glm::vec3 position,
                                       glm::vec3 geometric, glm::dvec3 shading);

struct ErrorStats {
  double mean = 0, p95 = 0;
};
ErrorStats error_stats(std::vector<double> errors);

// The mean of `values` and its standard error (independent samples).
struct MeanAndError {
  double mean = 0, standard_error = 0;
};
MeanAndError mean_and_error(const std::vector<double>& values);

}  // namespace lg::test
