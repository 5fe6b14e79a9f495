#include "nodes/lighting/deferred/nelder_mead.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lg {

NelderMeadResult minimize_nelder_mead(const std::function<double(const std::vector<double>&)>& f,
                                      std::vector<double> start, double step, double rel_tol, int max_evaluations) {
  const size_t n = start.size();
  std::vector<std::vector<double>> points(n + 1, start);
  for (size_t i = 0; i < n; ++i) points[i + 1][i] += step;
  std::vector<double> values(n + 1);
  int evaluations = 0;
  auto eval = [&](const std::vector<double>& x) {
    ++evaluations;
    const double y = f(x);
    return std::isfinite(y) ? y : HUGE_VAL;
  };
  for (size_t i = 0; i <= n; ++i) values[i] = eval(points[i]);
  // x = centroid + t (worst - centroid): t = -1 reflects, -2 expands, 0.5 contracts inside.
  auto along = [&](const std::vector<double>& centroid, const std::vector<double>& worst, double t) {
    std::vector<double> x(n);
    for (size_t k = 0; k < n; ++k) x[k] = centroid[k] + t * (worst[k] - centroid[k]);
    return x;
  };
  std::vector<size_t> order(n + 1);
  while (evaluations < max_evaluations) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
    const size_t best = order.front(), worst = order.back(), second = order[n - 1];
    if (values[worst] - values[best] <= rel_tol * std::fabs(values[best]) + 1e-300) break;
    std::vector<double> centroid(n, 0.0);
    for (size_t i = 0; i <= n; ++i)
      if (i != worst)
        for (size_t k = 0; k < n; ++k) centroid[k] += points[i][k] / double(n);
    std::vector<double> reflected = along(centroid, points[worst], -1.0);
    const double fr = eval(reflected);
    if (fr < values[best]) {
      std::vector<double> expanded = along(centroid, points[worst], -2.0);
      const double fe = eval(expanded);
      if (fe < fr) {
        points[worst] = expanded, values[worst] = fe;
      } else {
        points[worst] = reflected, values[worst] = fr;
      }
    } else if (fr < values[second]) {
      points[worst] = reflected, values[worst] = fr;
    } else {
      // Contract toward the better of the worst point and its reflection.
      const bool outside = fr < values[worst];
      std::vector<double> contracted = along(centroid, points[worst], outside ? -0.5 : 0.5);
      const double fc = eval(contracted);
      if (fc < std::min(fr, values[worst])) {
        points[worst] = contracted, values[worst] = fc;
      } else {
        for (size_t i = 0; i <= n; ++i) {
          if (i == best) continue;
          for (size_t k = 0; k < n; ++k) points[i][k] = 0.5 * (points[i][k] + points[best][k]);
          values[i] = eval(points[i]);
        }
      }
    }
  }
  const size_t best = size_t(std::min_element(values.begin(), values.end()) - values.begin());
  return {points[best], values[best], evaluations};
}

}  // namespace lg
