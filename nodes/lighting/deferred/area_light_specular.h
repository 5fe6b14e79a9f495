// Representative-point specular for area lights (Karis 2013): the point of the light closest to
// the reflection ray stands in for the whole light, and a normalisation factor takes back the
// energy the widened highlight would otherwise gain. Float math, to be ported to GLSL.
//
// Shade with it as with a point light at `direction` whose intensity is the area light's
// (radiance x projected area): f_r(v, direction) * saturate(n . direction) * E * normalization.
// `reflection` is the unit mirror direction reflect(-v, n); `alpha` is GGX alpha, clamped to
// at least kMinSpecularAlpha so that a mirror still gets a finite, widened lobe.
#pragma once

#include <glm/vec3.hpp>

#include "nodes/lighting/deferred/area_light.h"

namespace lg {

inline constexpr float kMinSpecularAlpha = 1e-4f;

struct RepresentativePoint {
  glm::vec3 direction;  // unit, from the shaded point toward the point on the light
  float distance;       // from the shaded point to that point
  float normalization;  // (alpha / alpha')^k in [0, 1]; 0 for no contribution
};

// The point of the sphere closest to the reflection ray; (alpha / alpha')^2 with
// alpha' = alpha + radius / (2 distance): the lobe widens by half the light's angular radius.
RepresentativePoint sphere_specular_point(const SphereLight& light, glm::vec3 p, glm::vec3 reflection, float alpha);
// The point of the segment closest to the reflection ray, then the sphere of the tube's radius
// there as above; times alpha / alpha'' for the length, which widens the lobe in one direction
// only, with alpha'' = alpha + length / (4 distance).
RepresentativePoint tube_specular_point(const TubeLight& light, glm::vec3 p, glm::vec3 reflection, float alpha);
// Where the reflection ray meets the light's plane (or, if it never does, its point at the
// light's distance projected on the plane), clamped to the rectangle; the normalisation is
// (alpha / alpha'_x) (alpha / alpha'_y) with alpha'_i = alpha + |half_i| / (2 distance).
// Behind a one-sided light the normalisation is 0.
RepresentativePoint rect_specular_point(const RectLight& light, glm::vec3 p, glm::vec3 reflection, float alpha);

}  // namespace lg
