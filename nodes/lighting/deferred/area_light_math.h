// Scalar helpers shared by the real-time area-light formulas, each with a GLSL built-in twin.
#pragma once

#include <cfloat>
#include <cmath>

namespace lg {

inline constexpr float kAreaLightPi = 3.14159265358979f;

inline bool is_finite(float x) {
  return x == x && std::fabs(x) <= FLT_MAX;
}

// NaN or Inf becomes 0, so one bad G-buffer texel cannot spread through later passes.
inline float finite_or_zero(float x) {
  return is_finite(x) ? x : 0.0f;
}

inline float clamp01(float x) {
  return std::fmin(std::fmax(x, 0.0f), 1.0f);
}

}  // namespace lg
