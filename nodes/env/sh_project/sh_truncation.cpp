#include "nodes/env/sh_project/sh_truncation.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <vector>

#include "nodes/env/common/sh_basis.h"
#include "nodes/env/irradiance/irradiance_reference.h"
#include "nodes/env/sh_project/sh_reference.h"

namespace lg {

double sh_irradiance_truncation_rms(const CubeImage& env, int order, int directions, uint64_t seed) {
  std::vector<double> factors(order + 1);
  for (int l = 0; l <= order; ++l) factors[l] = cosine_lobe_band(l);
  const std::vector<glm::dvec3> sh = project_sh_reference(env, order, factors).coefficients;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  double sum = 0;
  for (int d = 0; d < directions; ++d) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const glm::dvec3 exact = std::numbers::pi * irradiance_over_pi_reference(env, n), from_sh = evaluate_sh(sh, n);
    for (int c = 0; c < 3; ++c) sum += std::pow((from_sh[c] - exact[c]) / exact[c], 2);
  }
  return std::sqrt(sum / (3.0 * directions));
}

}  // namespace lg
