#include "nodes/gi/path_tracer/environment_map.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace lg {
namespace {

constexpr double kPi = std::numbers::pi;

double luminance(glm::dvec3 c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// The interval of a CDF (n + 1 ascending entries from 0 to 1) that u falls in, and where in it.
std::pair<uint32_t, double> invert_cdf(const double* cdf, uint32_t n, double u) {
  const uint32_t i = uint32_t(std::clamp<ptrdiff_t>(std::upper_bound(cdf, cdf + n + 1, u) - cdf - 1, 0, n - 1));
  const double width = cdf[i + 1] - cdf[i];
  return {i, width > 0.0 ? std::clamp((u - cdf[i]) / width, 0.0, 1.0) : 0.5};
}

}  // namespace

EnvironmentMap::EnvironmentMap(std::function<glm::dvec3(glm::dvec3)> radiance, uint32_t width, uint32_t height,
                               const std::function<double(uint32_t, uint32_t)>& texel_luminance)
    : radiance_(std::move(radiance)), width_(width), height_(height) {
  std::vector<double> weight(size_t(width) * height);
  double total = 0.0;
  for (uint32_t row = 0; row < height; ++row) {
    const double sin_theta = std::sin(kPi * (row + 0.5) / height);
    for (uint32_t col = 0; col < width; ++col) {
      const double l = texel_luminance(col, row);
      weight[size_t(row) * width + col] = (std::isfinite(l) ? std::max(l, 0.0) : 0.0) * sin_theta;
      total += weight[size_t(row) * width + col];
    }
  }
  // The defensive share: uniform in (u, v), so proportional to sin(theta) in solid angle too.
  const double floor_weight = total > 0.0 ? 0.01 * total / double(weight.size()) : 1.0;
  for (uint32_t row = 0; row < height; ++row) {
    const double sin_theta = std::sin(kPi * (row + 0.5) / height);
    for (uint32_t col = 0; col < width; ++col) weight[size_t(row) * width + col] += floor_weight * sin_theta;
  }
  total = 0.0;
  for (double w : weight) total += w;
  texel_probability_.resize(weight.size());
  row_cdf_.assign(height + 1, 0.0);
  column_cdf_.assign(size_t(height) * (width + 1), 0.0);
  for (uint32_t row = 0; row < height; ++row) {
    double row_sum = 0.0;
    double* cdf = &column_cdf_[size_t(row) * (width + 1)];
    for (uint32_t col = 0; col < width; ++col) {
      const double w = weight[size_t(row) * width + col];
      texel_probability_[size_t(row) * width + col] = w / total;
      row_sum += w;
      cdf[col + 1] = row_sum;
    }
    for (uint32_t col = 1; col <= width; ++col) cdf[col] = row_sum > 0.0 ? cdf[col] / row_sum : double(col) / width;
    row_cdf_[row + 1] = row_cdf_[row] + row_sum / total;
  }
  row_cdf_[height] = 1.0;
}

EnvironmentMap EnvironmentMap::from_image(Equirect image) {
  auto shared = std::make_shared<const Equirect>(std::move(image));
  const uint32_t width = std::max(shared->width, 1u), height = std::max(shared->height, 1u);
  return EnvironmentMap(
      [shared](glm::dvec3 d) {
        if (shared->rgba.empty()) return glm::dvec3(0.0);
        return glm::dvec3(sample_equirect(*shared, equirect_uv(d)));
      },
      width, height,
      [&](uint32_t col, uint32_t row) {
        if (shared->rgba.empty()) return 0.0;
        const float* t = &shared->rgba[(size_t(row) * shared->width + col) * 4];
        return luminance(glm::dvec3(t[0], t[1], t[2]));
      });
}

EnvironmentMap EnvironmentMap::from_sky(const SkyModel& model, uint32_t width) {
  const uint32_t height = std::max(width / 2, 1u);
  return EnvironmentMap([model](glm::dvec3 d) { return sky_radiance(model, d); }, width, height,
                        [&](uint32_t col, uint32_t row) {
                          const glm::dvec2 uv((col + 0.5) / width, (row + 0.5) / height);
                          return luminance(sky_radiance(model, equirect_direction(uv)));
                        });
}

double EnvironmentMap::pdf(glm::dvec3 direction) const {
  const glm::dvec2 uv = equirect_uv(direction);
  const uint32_t col = std::min(uint32_t(uv.x * width_), width_ - 1);
  const uint32_t row = std::min(uint32_t(uv.y * height_), height_ - 1);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - direction.y * direction.y));
  if (!(sin_theta > 0.0)) return 0.0;
  // d(omega) = 2 pi^2 sin(theta) du dv over the image.
  return texel_probability_[size_t(row) * width_ + col] * double(width_) * height_ / (2.0 * kPi * kPi * sin_theta);
}

std::optional<EnvironmentMap::Sample> EnvironmentMap::sample(glm::dvec2 u) const {
  const auto [row, v_in] = invert_cdf(row_cdf_.data(), height_, u.x);
  const auto [col, u_in] = invert_cdf(&column_cdf_[size_t(row) * (width_ + 1)], width_, u.y);
  const glm::dvec2 uv((col + u_in) / width_, (row + v_in) / height_);
  const glm::dvec3 direction = equirect_direction(uv);
  const double pdf = this->pdf(direction);
  if (!(pdf > 0.0)) return std::nullopt;
  return Sample{direction, radiance(direction), pdf};
}

}  // namespace lg
