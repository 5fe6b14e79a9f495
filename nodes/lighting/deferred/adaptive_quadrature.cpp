#include "nodes/lighting/deferred/adaptive_quadrature.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace lg {
namespace {

constexpr int kOrder = 10;

struct GaussLegendre {
  std::array<double, kOrder> nodes;  // on [-1, 1]
  std::array<double, kOrder> weights;
};

// Nodes are the roots of P_n, found by Newton's method from Chebyshev-like first guesses;
// weights are 2 / ((1 - x^2) P_n'(x)^2).
GaussLegendre make_gauss_legendre() {
  GaussLegendre rule{};
  for (int i = 0; i < kOrder; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (kOrder + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0;
      double p1 = x;
      for (int k = 2; k <= kOrder; ++k) {
        double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = kOrder * (x * p1 - p0) / (x * x - 1.0);
      double step = p1 / derivative;
      x -= step;
      if (std::fabs(step) < 1e-16) break;
    }
    rule.nodes[i] = x;
    rule.weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  return rule;
}

double gauss_legendre(const std::function<double(double)>& f, double a, double b) {
  static const GaussLegendre rule = make_gauss_legendre();
  double mid = 0.5 * (a + b);
  double half = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < kOrder; ++i) sum += rule.weights[i] * f(mid + half * rule.nodes[i]);
  return sum * half;
}

struct Interval {
  double a;
  double b;
  double value;  // from the two halves
  double error;  // |whole - halves|
};

Interval measure(const std::function<double(double)>& f, double a, double b) {
  double mid = 0.5 * (a + b);
  double halves = gauss_legendre(f, a, mid) + gauss_legendre(f, mid, b);
  return Interval{a, b, halves, std::fabs(gauss_legendre(f, a, b) - halves)};
}

}  // namespace

QuadratureResult integrate_adaptive(const std::function<double(double)>& f, double a, double b, double rel_tol,
                                    double abs_tol, int max_intervals) {
  long evaluations = 0;
  auto counted = [&](double x) {
    ++evaluations;
    return f(x);
  };
  auto by_error = [](const Interval& x, const Interval& y) { return x.error < y.error; };
  std::vector<Interval> heap{measure(counted, a, b)};
  double value = heap[0].value;
  double error = heap[0].error;
  while (error > std::max(abs_tol, rel_tol * std::fabs(value)) && static_cast<int>(heap.size()) < max_intervals) {
    std::pop_heap(heap.begin(), heap.end(), by_error);
    Interval worst = heap.back();
    heap.pop_back();
    double mid = 0.5 * (worst.a + worst.b);
    for (Interval part : {measure(counted, worst.a, mid), measure(counted, mid, worst.b)}) {
      heap.push_back(part);
      std::push_heap(heap.begin(), heap.end(), by_error);
    }
    // Re-summed rather than updated, so rounding cannot drift over thousands of splits.
    value = 0.0;
    error = 0.0;
    for (const Interval& i : heap) {
      value += i.value;
      error += i.error;
    }
  }
  return QuadratureResult{value, error, evaluations};
}

}  // namespace lg
