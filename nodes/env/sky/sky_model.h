// env.sky's model on the CPU in double precision (nodes/env/sky/shaders/sky.comp evaluates the
// same formulas from the coefficients computed here): Preetham, Shirley and Smits' analytic
// daylight (Perez distributions of luminance and chromaticity from turbidity), normalised so
// the zenith's luminance is 1, in linear Rec.709; a sun disk of radiance sun_intensity x the
// zenith; below the horizon a uniform Lambertian ground of albedo 0.3 lit by that sky and sun.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "nodes/env/common/cube_map.h"

namespace lg {

inline constexpr double kSunAngularRadius = 0.00465;  // radians, as DirectionalLightData's default
inline constexpr double kGroundAlbedo = 0.3;

struct SkyParams {
  glm::dvec3 sun_direction{0.3, 0.6, 0.4};  // towards the sun; normalised by the model
  double sun_intensity = 20;                // sun radiance / zenith luminance
  double turbidity = 3;
};

// Coefficients of the three Perez distributions (Y, x, y), each A..E, and what they are
// divided by (the distribution at the zenith) times the zenith's value.
struct SkyModel {
  glm::dvec3 sun;      // unit; +Y when the params give a zero vector
  glm::dvec3 sky_sun;  // the sun the sky is lit by: `sun` lifted to the horizon when below it
  double sun_radiance;
  std::array<std::array<double, 5>, 3> perez;
  std::array<double, 3> zenith_scale;  // zenith value / F(0, theta_sun) for Y, x, y
  glm::dvec3 ground;                   // radiance below the horizon
};

SkyModel make_sky_model(const SkyParams& params);

// The sky's radiance without the sun disk (the ground below the horizon).
glm::dvec3 sky_radiance(const SkyModel& model, const glm::dvec3& direction);

// The sun disk's solid angle.
double sun_solid_angle();

// The reference of one mip of env.sky: per texel, the sky integrated with texel_quadrature
// over each of subdivide^2 parts of the texel, plus the sun energy landing in the texel (the
// disk sampled at `sun_points` even points, those below the horizon dropped), over the texel's
// solid angle.
CubeImage render_sky_reference(const SkyModel& model, uint32_t size, uint32_t subdivide, int sun_points = 16384);

}  // namespace lg
