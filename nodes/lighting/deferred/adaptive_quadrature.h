// Adaptive Gauss-Legendre quadrature in one dimension, for the double-precision references.
#pragma once

#include <functional>

namespace lg {

struct QuadratureResult {
  double value = 0.0;
  double error = 0.0;    // estimated absolute error
  long evaluations = 0;  // of the integrand
};

// The integral of f over [a, b] to within max(abs_tol, rel_tol |value|). Each interval is
// measured by a 10-point Gauss-Legendre rule on itself and on its two halves: the halves' sum
// is kept and the difference is its error estimate (a conservative one: for smooth f the halves
// are about 2^-20 times closer). The interval with the largest estimate is halved until the sum
// of estimates meets the tolerance, or max_intervals is reached (the estimate then says so).
QuadratureResult integrate_adaptive(const std::function<double(double)>& f, double a, double b, double rel_tol,
                                    double abs_tol, int max_intervals = 4000);

}  // namespace lg
