// Random area-light configurations for the lighting tests (fixed seeds, never zeros): a light,
// a shaded point 1.5 to 50 bounding radii from its center, and a normal that has the light's
// whole bounding sphere above its horizon, or the horizon through that sphere.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <random>

#include "nodes/lighting/deferred/area_light.h"
#include "nodes/lighting/deferred/area_light_reference.h"

namespace lg {

enum class Horizon { kAbove, kCrossing };

struct Shading {
  glm::dvec3 p;
  glm::dvec3 n;
  double bound_irradiance;  // pi L (R/D)^2: the bounding sphere's, head-on; the error scale
};

class CaseGenerator {
 public:
  explicit CaseGenerator(uint64_t seed) : rng_(seed) {}

  SphereLightD sphere();
  TubeLightD tube();
  RectLightD rect();
  // A shaded point and normal for a light with this bounding sphere. A non-zero `front` keeps
  // p on the side it points to (for one-sided rectangles).
  Shading shading(glm::dvec3 center, double bounding_radius, double radiance, Horizon horizon,
                  glm::dvec3 front = glm::dvec3(0.0), double min_distance = 1.5, double max_distance = 50.0);

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double log_uniform(double lo, double hi);
  glm::dvec3 direction();

 private:
  std::mt19937_64 rng_;
};

double bounding_radius(const SphereLightD& light);
double bounding_radius(const TubeLightD& light);
double bounding_radius(const RectLightD& light);
glm::dvec3 light_center(const SphereLightD& light);
glm::dvec3 light_center(const TubeLightD& light);
glm::dvec3 light_center(const RectLightD& light);

glm::vec3 to_float(glm::dvec3 v);
SphereLight to_float(const SphereLightD& light);
TubeLight to_float(const TubeLightD& light);
RectLight to_float(const RectLightD& light);
// The configuration the float formulas see, back in double.
SphereLightD rounded(const SphereLightD& light);
TubeLightD rounded(const TubeLightD& light);
RectLightD rounded(const RectLightD& light);

}  // namespace lg
