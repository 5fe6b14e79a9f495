#include "editor/env_probe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lg {

double luminance(const Vec3d& rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

static Vec3d texel(const ImageData& image, int64_t col, int64_t row) {
  const int64_t w = image.width, h = image.height;
  col = ((col % w) + w) % w;
  row = std::clamp<int64_t>(row, 0, h - 1);
  const float* t = &image.rgba[(size_t(row) * w + size_t(col)) * 4];
  return {t[0], t[1], t[2]};
}

Vec3d sample_equirect(const ImageData& image, const Vec3d& d) {
  const auto uv = equirect_uv(d);
  const double x = uv[0] * image.width - 0.5, y = uv[1] * image.height - 0.5;
  const auto x0 = int64_t(std::floor(x)), y0 = int64_t(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  Vec3d out{};
  for (int c = 0; c < 3; ++c)
    out[c] = (1 - fy) * ((1 - fx) * texel(image, x0, y0)[c] + fx * texel(image, x0 + 1, y0)[c]) +
             fy * ((1 - fx) * texel(image, x0, y0 + 1)[c] + fx * texel(image, x0 + 1, y0 + 1)[c]);
  return out;
}

EnvProbe make_env_probe(std::string path, ImageData image) {
  EnvProbe probe;
  probe.path = std::move(path);
  probe.sh = project_equirect_sh_l2(image.width, image.height, image.rgba);
  double sum = 0, sum_sq = 0, err_sq = 0, area = 0, negative = 0;
  for (uint32_t row = 0; row < image.height; ++row) {
    const double w = equirect_texel_solid_angle(row, image.width, image.height);
    for (uint32_t col = 0; col < image.width; ++col) {
      const Vec3d radiance = texel(image, col, row);
      const double l = luminance(radiance);
      if (!std::isfinite(l)) continue;
      const Vec3d d = equirect_direction((col + 0.5) / image.width, (row + 0.5) / image.height);
      const double sh = luminance(evaluate_sh_l2(probe.sh, d)), e = sh - l;
      sum += w * l, sum_sq += w * l * l, err_sq += w * e * e, area += w;
      if (sh < 0) negative += w;
    }
  }
  if (area > 0) {
    probe.mean_luminance = sum / area;
    probe.rms_error = std::sqrt(err_sq / area);
    const double rms = std::sqrt(sum_sq / area);
    probe.relative_rms_error = rms > 0 ? probe.rms_error / rms : 0;
    probe.negative_fraction = negative / area;
  }
  probe.image = std::move(image);
  return probe;
}

EnvProbe load_env_probe(const std::string& path) {
  return make_env_probe(path, load_image(path));
}

}  // namespace lg
