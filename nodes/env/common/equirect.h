// The equirectangular (latitude-longitude) convention of env files, on the CPU: column u runs
// with the azimuth phi = atan2(x, -z) as u = 0.5 + phi / (2 pi) (the image centre looks down
// -Z, +X a quarter to the right), row v = acos(y) / pi (the top row is +Y). Resampling to a
// cube map (env.load's reference).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "nodes/env/common/cube_map.h"

namespace lg {

struct Equirect {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;  // rows top to bottom
};

glm::dvec2 equirect_uv(const glm::dvec3& direction);  // in [0, 1]^2
glm::dvec3 equirect_direction(const glm::dvec2& uv);

// Scales the RGB of `rgba` by `intensity` and replaces non-finite texels by 0, in place, as
// env.load and the CPU tracers do with an env file; returns how many texels held NaN or Inf.
uint64_t sanitize_equirect(std::span<float> rgba, double intensity);

// Bilinear, wrapping around in u and clamped at the poles.
glm::dvec4 sample_equirect(const Equirect& image, const glm::dvec2& uv);

// Each texel the mean of supersample^2 bilinear samples spread evenly over it.
CubeImage equirect_to_cube(const Equirect& image, uint32_t face_size, int supersample);

}  // namespace lg
