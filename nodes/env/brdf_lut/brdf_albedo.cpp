#include "nodes/env/brdf_lut/brdf_albedo.h"

#include <algorithm>
#include <cmath>

#include "nodes/env/brdf_lut/dfg_reference.h"

namespace lg {

const float kBrdfAlbedoTable[2 * kBrdfAlbedoSize * kBrdfAlbedoSize] = {
#include "nodes/env/brdf_lut/brdf_albedo_table.inc"
};

glm::dvec2 brdf_albedo_reference(double n_dot_v, double roughness, int steps) {
  constexpr double min_alpha = 1e-3;  // brdf.glsl's LG_MIN_ALPHA
  return dfg_reference(std::max(n_dot_v, 1e-4), std::max(roughness, std::sqrt(min_alpha)), steps);
}

double brdf_albedo_column(double n_dot_v) {
  return std::sqrt(std::sqrt(std::clamp(n_dot_v, 0.0, 1.0))) * (kBrdfAlbedoSize - 1);
}

std::array<glm::vec4, kBrdfAlbedoSize * kBrdfAlbedoSize / 2> brdf_albedo_texels() {
  std::array<glm::vec4, kBrdfAlbedoSize * kBrdfAlbedoSize / 2> texels;
  for (size_t k = 0; k < texels.size(); ++k)
    texels[k] = glm::vec4(kBrdfAlbedoTable[4 * k], kBrdfAlbedoTable[4 * k + 1], kBrdfAlbedoTable[4 * k + 2],
                          kBrdfAlbedoTable[4 * k + 3]);
  return texels;
}

glm::dvec2 brdf_albedo_lookup(double n_dot_v, double roughness) {
  constexpr int last = kBrdfAlbedoSize - 1;
  const double x = brdf_albedo_column(n_dot_v), y = std::clamp(roughness, 0.0, 1.0) * last;
  const int x0 = std::min(int(x), last - 1), y0 = std::min(int(y), last - 1);
  const double fx = x - x0, fy = y - y0;
  auto at = [](int i, int j) {
    const float* t = &kBrdfAlbedoTable[2 * (j * kBrdfAlbedoSize + i)];
    return glm::dvec2(t[0], t[1]);
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
         fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

double white_albedo(glm::dvec2 scale_bias) {
  return std::max(scale_bias.x + scale_bias.y, 1e-4);
}

glm::dvec3 specular_energy_scale(glm::dvec3 f0, glm::dvec2 scale_bias) {
  return 1.0 + f0 * (1.0 / white_albedo(scale_bias) - 1.0);
}

glm::dvec3 specular_albedo(glm::dvec3 f0, glm::dvec2 scale_bias) {
  return (f0 * scale_bias.x + scale_bias.y) * specular_energy_scale(f0, scale_bias);
}

}  // namespace lg
