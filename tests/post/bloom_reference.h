// The kernel post.bloom's mip chain stands for, and the direct convolution with it in double
// precision that its tests and benchmark compare against.
//
// The chain (nodes/post/bloom/shaders) is linear with the threshold at 0. Level l (0 is half
// resolution) is the level above it box-filtered over 4 x 4 texels and decimated by 2; on the way
// up each level adds the level below it through a 3 x 3 tent ([1 2 1] / 4 per axis) of bilinear
// taps one coarse texel apart, and the composite samples level 0 bilinearly; the bloom is that sum
// over `levels`, divided by it. Every step is a product of one kernel in x and one in y, so the
// chain is the sum over levels of separable paths. A path through level l is not shift
// invariant (level l has one texel in s = 2^(l+1) pixels), so its kernel is defined as its
// impulse response averaged over the s x s positions of the impulse against that grid. That
// average is exactly a convolution: k_l = (T_l * D_l) / s, with D_l the down-filters convolved
// (4-tap boxes at spacings 1, 2, 4, ... 2^l pixels) and T_l the up-filters convolved (the tents
// between levels and the final bilinear). The stated kernel of `levels` is then
//   K(x, y) = (1 / levels) sum_{l < levels} k_l(x) k_l(y),
// close to a sum of Gaussians (k_l's standard deviation is about 1.4 s). What the chain adds to
// it is its shift variance (the phase of a detail against each level's grid), the rgba16f
// levels, and at image borders its clamped taps, where the reference extends the image by its
// edge texels.
#pragma once

#include <cstdint>
#include <vector>

#include "tests/post/exposure_harness.h"

namespace lg::test {

// k_l over pixel offsets -r..r (r = (size - 1) / 2), summing to 1.
std::vector<double> bloom_level_kernel(uint32_t level);

// `image` convolved with k(x) k(y), the image extended by its edge texels (alpha copied).
HostImage convolve_separable(const HostImage& image, const std::vector<double>& kernel);

// `image` convolved with K for `levels`: the bloom term post.bloom should produce.
HostImage bloom_reference(const HostImage& image, uint32_t levels);

}  // namespace lg::test
