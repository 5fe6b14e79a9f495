// Double-precision reference irradiance from sphere, tube (capsule) and rectangle area lights:
// E = integral over the light's surface of L cos(theta_p) cos(theta_l) / d^2 dA, counting only
// surface elements above the horizon of n that face p (for a convex light, exactly the part p
// sees). Used by the accuracy tests and benchmarks of the real-time formulas.
#pragma once

#include <glm/vec3.hpp>

#include "nodes/lighting/deferred/adaptive_quadrature.h"

namespace lg {

struct SphereLightD {
  glm::dvec3 center;
  double radius;
  double radiance;
};

// A capsule, as TubeLight.
struct TubeLightD {
  glm::dvec3 end0;
  glm::dvec3 end1;
  double radius;
  double radiance;
};

// As RectLight: perpendicular half-axes, one-sided lights emit toward cross(half_x, half_y).
struct RectLightD {
  glm::dvec3 center;
  glm::dvec3 half_x;
  glm::dvec3 half_y;
  double radiance;
  bool two_sided;
};

// Each surface is swept by circles (rows for the rectangle): the inner integral runs over the
// arcs of a circle that face p and lie above the horizon, found in closed form so the integrand
// is smooth on them; the outer integral over the circles is split where those arcs appear or
// vanish (also in closed form) and is adaptive between. `error` is the outer estimate plus the
// inner tolerance (scaled up if an inner integral stopped at its rounding floor). The target is
// max(rel_tol E, 1e-3 rel_tol E_max), E_max being that of the light's bounding sphere seen
// head-on. Against closed forms, rel_tol 1e-11 gives 1e-9 relative (README.md).
// p on or inside a sphere or capsule sees no front face: E = 0.
QuadratureResult reference_sphere_irradiance(const SphereLightD& light, glm::dvec3 p, glm::dvec3 n,
                                             double rel_tol = 1e-10);
QuadratureResult reference_tube_irradiance(const TubeLightD& light, glm::dvec3 p, glm::dvec3 n, double rel_tol = 1e-10);
QuadratureResult reference_rect_irradiance(const RectLightD& light, glm::dvec3 p, glm::dvec3 n, double rel_tol = 1e-10);

// The GGX lobe of brdf.glsl without Fresnel or multiple scattering, f = D Vis, at unit view v
// (toward the eye) and alpha (not floored here).
struct SpecularLobe {
  glm::dvec3 v;
  double alpha;
};

// The radiance the lobe reflects toward v from the light, L x integral of f(v, l) (n.l) over the
// directions l to the part of the light p sees, integrated as the irradiance above (the lobe a
// weight on each direction). Each smooth interval is first cut into pieces about the lobe's
// width (up to 32), so that a narrow lobe is found; the absolute floor is 1e-3 rel_tol of the
// most the lobe can gather (L min(1, (R / D)^2 / alpha^2)). Used by the specular accuracy tests
// and lumagraph-bench-area-specular.
QuadratureResult reference_sphere_specular(const SphereLightD& light, glm::dvec3 p, glm::dvec3 n,
                                           const SpecularLobe& lobe, double rel_tol = 1e-6);
QuadratureResult reference_tube_specular(const TubeLightD& light, glm::dvec3 p, glm::dvec3 n, const SpecularLobe& lobe,
                                         double rel_tol = 1e-6);
QuadratureResult reference_rect_specular(const RectLightD& light, glm::dvec3 p, glm::dvec3 n, const SpecularLobe& lobe,
                                         double rel_tol = 1e-6);

}  // namespace lg
