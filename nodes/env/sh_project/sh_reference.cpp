#include "nodes/env/sh_project/sh_reference.h"

#include <cmath>

#include "nodes/env/common/sh_basis.h"

namespace lg {

ShReference project_sh_reference(const CubeImage& env, int order, std::span<const double> band_factors) {
  ShReference out;
  out.coefficients.assign(sh_count(order), glm::dvec3(0.0));
  std::vector<double> y(sh_count(order));
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < env.size; ++j)
      for (uint32_t i = 0; i < env.size; ++i) {
        const glm::dvec3 radiance(env.at(f, i, j));
        if (!std::isfinite(radiance.x) || !std::isfinite(radiance.y) || !std::isfinite(radiance.z)) {
          ++out.non_finite;
          continue;
        }
        for (const TexelSample& s : texel_quadrature(f, env.size, i, j)) {
          sh_evaluate(order, s.direction, y);
          for (size_t k = 0; k < y.size(); ++k) out.coefficients[k] += radiance * (s.weight * y[k]);
        }
      }
  for (int l = 0; l <= order; ++l)
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) out.coefficients[k] *= band_factors[l];
  return out;
}

glm::dvec3 evaluate_sh(std::span<const glm::dvec3> coefficients, const glm::dvec3& direction) {
  const int order = int(std::lround(std::sqrt(double(coefficients.size())))) - 1;
  std::vector<double> y(coefficients.size());
  sh_evaluate(order, direction, y);
  glm::dvec3 sum(0.0);
  for (size_t k = 0; k < y.size(); ++k) sum += coefficients[k] * y[k];
  return sum;
}

}  // namespace lg
