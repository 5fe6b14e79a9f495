// References for lighting.ibl's occlusion formulas (nodes/lighting/ibl/ibl_occlusion.h), by
// brute-force quadrature in double precision, for tests: the irradiance through a visibility
// cone and the solid angle two cones share.
#pragma once

#include <functional>
#include <glm/vec3.hpp>

namespace lg {

// The integral of radiance(w) V(w) max(0, n . w) over the sphere, V the indicator of the cone
// about `axis` with half-angle cosine `cone_cos`: midpoint rule in (cos theta, phi) about the
// axis, where the solid angle is uniform (`steps` x 2 `steps` points).
glm::dvec3 cone_irradiance_quadrature(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, const glm::dvec3& n,
                                      const glm::dvec3& axis, double cone_cos, int steps);

// The solid angle of the intersection of two cones (unit axes, half-angle cosines): midpoint
// rule in cos theta over the second cone, the arc of each ring inside the first measured
// exactly (`steps` rings).
double cone_intersection_quadrature(const glm::dvec3& axis1, double cos1, const glm::dvec3& axis2, double cos2,
                                    int steps);

}  // namespace lg
