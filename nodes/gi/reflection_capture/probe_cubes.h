// gi.reflection_capture's images on the device: per probe its captured radiance (a cube, mip 0
// only, which a capture writes) and the prefilter's chain and result, and the cube array the
// lookup reads (cube i for probe i, at least one cube, black until a probe is prefiltered into it).
// prefilter() runs env.specular_prefilter's record_specular_prefilter() on chosen probes and
// copies their GGX mip chains into the array.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/image.h"

namespace lg {

class ProbeCubes {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

  // Makes images for `count` probes of `size`-texel faces and `mips` prefiltered levels, unless
  // it has them already: true when they are new (every captured cube undefined, in
  // READ_ONLY_OPTIMAL; the array cleared to black, in READ_ONLY_OPTIMAL).
  bool prepare(PassContext& ctx, size_t count, uint32_t size, uint32_t mips);

  // Prefilters the captured cubes of `probes` (READ_ONLY_OPTIMAL, as left) with `samples` GGX
  // samples a texel into their places in the array.
  void prefilter(PassContext& ctx, std::span<const uint32_t> probes, uint32_t samples);

  std::span<Image> captured() { return captured_; }
  Image& array() { return *array_; }
  // The array's cube `probe` alone, as a cube view (the second bounce's specular map).
  VkImageView cube_view(uint32_t probe);

 private:
  struct Chain {
    Image chain, prefiltered;
  };
  std::vector<Image> captured_;
  std::vector<Chain> chains_;
  std::optional<Image> array_;
  uint32_t size_ = 0, mips_ = 0;
};

}  // namespace lg
