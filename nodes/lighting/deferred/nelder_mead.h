// Nelder-Mead's downhill simplex: minimises a function of a few variables without derivatives
// (the LTC fit, ltc_fit.h).
#pragma once

#include <functional>
#include <vector>

namespace lg {

struct NelderMeadResult {
  std::vector<double> x;
  double value = 0.0;
  int evaluations = 0;
};

// From `start` with a simplex of `step` along each axis; stops when the simplex's values differ by
// at most rel_tol of the best (plus 1e-300) or after max_evaluations. Deterministic.
NelderMeadResult minimize_nelder_mead(const std::function<double(const std::vector<double>&)>& f,
                                      std::vector<double> start, double step, double rel_tol, int max_evaluations);

}  // namespace lg
