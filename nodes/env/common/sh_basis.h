// The real spherical-harmonic basis of the env nodes (nodes/env/common/shaders/sh_basis.glsl is
// the same on the GPU; docs/sh-basis.md states it): orthonormal over the sphere, coefficient
// index l (l + 1) + m for m = -l..l, polar axis +Z, no Condon-Shortley phase, so
// Y_1,-1 ~ +y, Y_1,0 ~ +z, Y_1,1 ~ +x. Also the cosine-lobe convolution and ringing windows.
#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <string_view>
#include <vector>

namespace lg {

inline constexpr int kMaxShOrder = 4;
constexpr int sh_count(int order) {
  return (order + 1) * (order + 1);
}

// Y_lm(direction) for every l <= order into out[l (l + 1) + m]; `direction` is unit.
void sh_evaluate(int order, const glm::dvec3& direction, std::span<double> out);

// The factor that turns band-l radiance coefficients into irradiance coefficients,
// sqrt(4 pi / (2l + 1)) times the zonal coefficient of max(cos, 0): pi, 2pi/3, pi/4, 0, -pi/24.
double cosine_lobe_band(int l);

enum class ShWindow { none, hanning, lanczos, min_ringing };
ShWindow sh_window_from_name(std::string_view name);  // throws on an unknown name

// Per-band factors w_0..w_order of a window. min_ringing: Sloan's w_l = 1 / (1 + lambda l^2
// (l+1)^2) with the smallest lambda whose impulse response (with the cosine lobe when
// `convolved`) has no negative lobe deeper than `target` times its peak.
std::vector<double> sh_window(ShWindow window, int order, double target, bool convolved);

// The zonal impulse response sum_l factor_l (2l + 1) / (4 pi) P_l(cos theta) of per-band factors.
double sh_impulse_response(std::span<const double> band_factors, double cos_theta);

}  // namespace lg
