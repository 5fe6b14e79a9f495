#include "tests/lighting/specular_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "runtime/scene/make_scene_view.h"

namespace lg::test {

bool SurfaceMask::contains(size_t pixel, const float* material) const {
  return material[1] > 0.5f && (roughness < 0.0f || std::abs(material[0] - roughness) < 0.005f) &&
         (pixels == nullptr || (*pixels)[pixel] != 0);
}

SpecularError specular_error(const ReferenceImage& reference, const std::vector<float>& lit,
                             const std::vector<float>& direct, const std::vector<float>& material, SurfaceMask mask) {
  const auto& mean = reference.mean_of(ReferenceAov::specular);
  const auto& error = reference.error_of(ReferenceAov::specular);
  double truth_sum = 0, error_sum = 0, noise_sum = 0;
  SpecularError out;
  for (size_t i = 0; i < reference.pixel_count(); ++i) {
    if (!mask.contains(i, &material[4 * i])) continue;
    ++out.pixels;
    for (int c = 0; c < 3; ++c) {
      truth_sum += mean[i][c];
      error_sum += std::abs(lit[4 * i + c] - direct[4 * i + c] - mean[i][c]);
      noise_sum += error[i][c];
    }
  }
  if (truth_sum > 0) out.relative = error_sum / truth_sum, out.noise = noise_sum / truth_sum;
  return out;
}

DebiasedError debiased_specular_error(const ReferenceImage& a, const ReferenceImage& b, const std::vector<float>& lit,
                                    const std::vector<float>& direct, const std::vector<float>& material,
                                    SurfaceMask mask) {
  if (a.pixel_count() != b.pixel_count() || a.width != b.width)
    throw std::invalid_argument("debiased_specular_error: the two references differ in size");
  const auto& mean_a = a.mean_of(ReferenceAov::specular);
  const auto& mean_b = b.mean_of(ReferenceAov::specular);
  double truth_sum = 0, cross_sum = 0, plain_sum = 0, noise_sum = 0;
  size_t values = 0;
  DebiasedError out;
  for (size_t i = 0; i < a.pixel_count(); ++i) {
    if (!mask.contains(i, &material[4 * i])) continue;
    ++out.pixels;
    for (int c = 0; c < 3; ++c) {
      const double x = double(lit[4 * i + c]) - direct[4 * i + c], ra = mean_a[i][c], rb = mean_b[i][c];
      const double m = 0.5 * (ra + rb);
      truth_sum += m;
      cross_sum += (x - ra) * (x - rb);
      plain_sum += (x - m) * (x - m);
      noise_sum += 0.25 * (ra - rb) * (ra - rb);
      ++values;
    }
  }
  if (values == 0 || truth_sum <= 0) return out;
  const double mean = truth_sum / double(values), n = double(values);
  out.rms = std::sqrt(std::max(0.0, cross_sum / n)) / mean;
  out.plain_rms = std::sqrt(plain_sum / n) / mean;
  out.noise_rms = std::sqrt(noise_sum / n) / mean;
  return out;
}

ReferenceImage average_references(const ReferenceImage& a, const ReferenceImage& b) {
  if (a.pixel_count() != b.pixel_count() || a.width != b.width)
    throw std::invalid_argument("average_references: the two references differ in size");
  ReferenceImage out = a;
  for (size_t aov = 0; aov < kReferenceAovCount; ++aov)
    for (size_t i = 0; i < out.mean[aov].size(); ++i) {
      out.mean[aov][i] = 0.5f * (a.mean[aov][i] + b.mean[aov][i]);
      const glm::vec3 ea = a.standard_error[aov][i], eb = b.standard_error[aov][i];
      out.standard_error[aov][i] = 0.5f * glm::sqrt(ea * ea + eb * eb);
    }
  out.non_finite_samples = a.non_finite_samples + b.non_finite_samples;
  return out;
}

std::vector<float> specular_error_picture(const ReferenceImage& reference, const std::vector<float>& lit,
                                          const std::vector<float>& direct, const std::vector<float>& material,
                                          SurfaceMask mask, double scale) {
  const auto& truth = reference.mean_of(ReferenceAov::specular);
  double truth_sum = 0;
  size_t pixels = 0;
  for (size_t i = 0; i < reference.pixel_count(); ++i)
    if (mask.contains(i, &material[4 * i])) truth_sum += (truth[i].x + truth[i].y + truth[i].z) / 3.0, ++pixels;
  const double mean = pixels > 0 && truth_sum > 0 ? truth_sum / double(pixels) : 1.0;
  const size_t w = reference.width, h = reference.pixel_count() / w;
  std::vector<float> out(3 * w * h * 4, 0.0f);
  const auto put = [&](size_t panel, size_t i, float r, float g, float b) {
    float* o = &out[4 * ((i / w) * 3 * w + panel * w + i % w)];
    o[0] = r, o[1] = g, o[2] = b;
  };
  const auto shown = [&](double x) { return float(std::max(x, 0.0) / mean / (1.0 + std::max(x, 0.0) / mean)); };
  for (size_t i = 0; i < reference.pixel_count(); ++i) {
    for (size_t panel = 0; panel < 3; ++panel) out[4 * ((i / w) * 3 * w + panel * w + i % w) + 3] = 1.0f;
    if (!mask.contains(i, &material[4 * i])) continue;
    double ours[3], signed_error = 0;
    for (int c = 0; c < 3; ++c) {
      ours[c] = lit[4 * i + c] - direct[4 * i + c];
      signed_error += (ours[c] - truth[i][c]) / 3.0;
    }
    put(0, i, shown(ours[0]), shown(ours[1]), shown(ours[2]));
    put(1, i, shown(truth[i].x), shown(truth[i].y), shown(truth[i].z));
    const float e = float(std::clamp(signed_error / (scale * mean), -1.0, 1.0));
    put(2, i, std::max(e, 0.0f), 0.0f, std::max(-e, 0.0f));
  }
  return out;
}

ReferenceImage trace_specular_reference(const World& world, uint32_t width, uint32_t height, uint32_t paths,
                                        const PathEnvironment& environment, uint64_t seed) {
  const PathScene scene(make_scene_view(world, float(width) / float(height)), environment);
  PathTracerOptions o;
  o.width = width, o.height = height, o.samples_per_pixel = paths, o.seed = seed;
  return trace_reference(scene, o);
}

}  // namespace lg::test
