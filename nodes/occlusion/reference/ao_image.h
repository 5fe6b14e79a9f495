// A reference ambient-occlusion image: per pixel the visibility k_A and the bent normal with its
// cone, NaN where the pixel has no reference (no surface there, or a pixel left out by a
// stride); error_against() compares a GPU result with it over the pixels both cover.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace lg {

struct AoImage {
  uint32_t width = 0, height = 0;
  std::vector<float> visibility;  // width * height, rows top down; NaN: no reference here
  std::vector<glm::vec4> bent;    // world-space bent normal (xyz) and cone cosine (w)

  AoImage() = default;
  AoImage(uint32_t w, uint32_t h);
  bool covered(size_t pixel) const { return std::isfinite(visibility[pixel]); }
  size_t covered_count() const;
};

struct AoError {
  double mean_absolute = 0, p95 = 0, max = 0;
  double mean_signed = 0;  // result - reference: negative where the result is too dark
  size_t pixels = 0;
};

// `result`: float RGBA rows as Executor::read_image returns them (occlusion in red), or one
// float per pixel when `channels` is 1; pixels the reference does not cover are left out.
AoError error_against(const AoImage& reference, const std::vector<float>& result, int channels = 4);
// The same between two references (over pixels both cover): e.g. height field against scene.
AoError error_against(const AoImage& reference, const AoImage& other);

// A binary file (magic, size, then the arrays) so benchmarks can keep a slow reference; load
// returns false for a missing, truncated or different-sized file.
void save_ao_image(const std::string& path, const AoImage& image);
bool load_ao_image(const std::string& path, AoImage& image);

}  // namespace lg
