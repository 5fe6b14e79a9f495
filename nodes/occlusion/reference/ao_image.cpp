#include "nodes/occlusion/reference/ao_image.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace lg {
namespace {

constexpr char kMagic[8] = {'L', 'G', 'A', 'O', 'R', 'E', 'F', '1'};

AoError summarize(std::vector<double> errors, double signed_sum) {
  AoError e;
  e.pixels = errors.size();
  if (errors.empty()) return e;
  double sum = 0;
  for (double v : errors) sum += v;
  e.mean_absolute = sum / errors.size();
  e.mean_signed = signed_sum / errors.size();
  const size_t k = std::min(errors.size() - 1, size_t(0.95 * errors.size()));
  std::nth_element(errors.begin(), errors.begin() + k, errors.end());
  e.p95 = errors[k];
  e.max = *std::max_element(errors.begin(), errors.end());
  return e;
}

}  // namespace

AoImage::AoImage(uint32_t w, uint32_t h)
    : width(w),
      height(h),
      visibility(size_t(w) * h, std::numeric_limits<float>::quiet_NaN()),
      bent(size_t(w) * h, glm::vec4(0.0f)) {}

size_t AoImage::covered_count() const {
  return size_t(std::count_if(visibility.begin(), visibility.end(), [](float v) { return std::isfinite(v); }));
}

AoError error_against(const AoImage& reference, const std::vector<float>& result, int channels) {
  const size_t n = size_t(reference.width) * reference.height;
  if (result.size() != n * size_t(channels))
    throw std::invalid_argument("error_against: the result has " + std::to_string(result.size()) +
                                " values, expected " + std::to_string(n * channels) + " for a " +
                                std::to_string(reference.width) + "x" + std::to_string(reference.height) + " image");
  std::vector<double> errors;
  double signed_sum = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!reference.covered(i)) continue;
    const double d = double(result[i * channels]) - reference.visibility[i];
    errors.push_back(std::abs(d));
    signed_sum += d;
  }
  return summarize(std::move(errors), signed_sum);
}

AoError error_against(const AoImage& reference, const AoImage& other) {
  if (reference.width != other.width || reference.height != other.height)
    throw std::invalid_argument("error_against: references of different sizes");
  std::vector<double> errors;
  double signed_sum = 0;
  for (size_t i = 0; i < reference.visibility.size(); ++i) {
    if (!reference.covered(i) || !other.covered(i)) continue;
    const double d = double(other.visibility[i]) - reference.visibility[i];
    errors.push_back(std::abs(d));
    signed_sum += d;
  }
  return summarize(std::move(errors), signed_sum);
}

void save_ao_image(const std::string& path, const AoImage& image) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    out.write(kMagic, sizeof kMagic);
    out.write(reinterpret_cast<const char*>(&image.width), sizeof image.width);
    out.write(reinterpret_cast<const char*>(&image.height), sizeof image.height);
    out.write(reinterpret_cast<const char*>(image.visibility.data()), std::streamsize(image.visibility.size() * 4));
    out.write(reinterpret_cast<const char*>(image.bent.data()), std::streamsize(image.bent.size() * 16));
    if (!out) throw std::runtime_error(partial + ": could not write the AO reference");
  }
  std::filesystem::rename(partial, path);  // never leaves a half-written cache under the name
}

bool load_ao_image(const std::string& path, AoImage& image) {
  std::ifstream in(path, std::ios::binary);
  char magic[sizeof kMagic];
  uint32_t w = 0, h = 0;
  if (!in.read(magic, sizeof magic) || !std::equal(magic, magic + sizeof magic, kMagic)) return false;
  if (!in.read(reinterpret_cast<char*>(&w), 4) || !in.read(reinterpret_cast<char*>(&h), 4)) return false;
  if (w != image.width || h != image.height) return false;
  AoImage loaded(w, h);
  if (!in.read(reinterpret_cast<char*>(loaded.visibility.data()), std::streamsize(loaded.visibility.size() * 4)) ||
      !in.read(reinterpret_cast<char*>(loaded.bent.data()), std::streamsize(loaded.bent.size() * 16)))
    return false;
  image = std::move(loaded);
  return true;
}

}  // namespace lg
