// The environment a ray escapes into, as the path tracer meets and samples it: an
// equirectangular image (env.load's file, its intensity applied and non-finite texels zeroed
// as env.load does, read bilinearly in the env convention of nodes/env/common/equirect.h) or env.sky's analytic sky
// without its sun disk (the sun is a distant disk of PathLights, sampled by its cone). Directions are importance
// sampled from a piecewise-constant table of luminance x sin(theta) over equirect texels, with
// 1% of the mean mixed in everywhere so that no direction that carries light has density 0.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "nodes/env/common/equirect.h"
#include "nodes/env/sky/sky_model.h"

namespace lg {

class EnvironmentMap {
 public:
  static EnvironmentMap from_image(Equirect image);
  // `width` x width/2 texels of the table; the sky is evaluated exactly, the table only guides.
  static EnvironmentMap from_sky(const SkyModel& model, uint32_t width = 512);

  glm::dvec3 radiance(glm::dvec3 direction) const { return radiance_(direction); }
  double pdf(glm::dvec3 direction) const;

  struct Sample {
    glm::dvec3 direction, radiance;
    double pdf = 0.0;
  };
  std::optional<Sample> sample(glm::dvec2 u) const;

 private:
  EnvironmentMap(std::function<glm::dvec3(glm::dvec3)> radiance, uint32_t width, uint32_t height,
                 const std::function<double(uint32_t col, uint32_t row)>& luminance);

  std::function<glm::dvec3(glm::dvec3)> radiance_;
  uint32_t width_ = 0, height_ = 0;
  std::vector<double> row_cdf_;     // height + 1 entries, from 0 to 1
  std::vector<double> column_cdf_;  // per row, width + 1 entries, from 0 to 1
  std::vector<double> texel_probability_;
};

}  // namespace lg
