// A test image beside a real G-buffer, for the nodes that a G-buffer guides (post.bilateral,
// post.upsample): scene.gbuffer draws the Cornell box (examples/worlds/cornell-box.json: walls,
// two blocks in front of them, depth steps at their silhouettes and sky around the open box),
// test.image feeds the host image, and the node under test (id "node") reads both.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tests/post/exposure_harness.h"

namespace lg::test {

// A graph with test.image "src" at `image_scale` of the frame, scene.gbuffer "gbuf" at
// `gbuffer_scale` of it, and `node` (a node's JSON object with id "node") linked to both
// through its inputs "color" and "gbuffer".
std::string guided_graph(std::string_view node, double image_scale = 1, double gbuffer_scale = 1);

// Puts the Cornell box, seen by its camera, into the harness's scene.
void show_cornell_box(ExposureHarness& h, uint32_t frame_width, uint32_t frame_height);

// The message of what one frame throws; empty if it throws nothing.
std::string frame_error(ExposureHarness& h);

// The G-buffer's device depth after a frame, one float a pixel (reversed Z: 0 is the sky).
std::vector<float> gbuffer_depth(ExposureHarness& h);

struct Guide {
  std::vector<float> depth;  // device depth, 0: the sky
  float near_plane = 0;
};

// The Cornell box's G-buffer depth at `width` x `height` (one frame of a graph that filters a
// constant image with it).
Guide cornell_box_guide(Context& context, uint32_t width, uint32_t height);

// An image of `width` x `height` whose every pixel is `rgba`.
HostImage constant_image(uint32_t width, uint32_t height, const float (&rgba)[4]);

// Each surface pixel's view distance (reversed-Z device depth is near / distance) in all three
// channels, times uniform noise in [1 - noise, 1 + noise] from `seed` per channel; the sky 1.
// Smooth on each surface (without noise) with jumps at silhouettes.
HostImage distance_image(const std::vector<float>& depth, float near_plane, uint32_t width, uint32_t height,
                         float noise = 0, unsigned seed = 0);

// A smooth function over a width x height G-buffer, in [1, 2]: 1.5 + sin and cos terms of 1.5
// and 1 periods across it. Its partial derivatives are at most smooth_slope().
double smooth_value(double x, double y, uint32_t width, uint32_t height);
struct Slope {
  double x, y;
};
Slope smooth_slope(uint32_t width, uint32_t height);

// The image at 1/k of a width x height G-buffer (floor(width / k) x floor(height / k)) whose
// texel i holds smooth_value at the G-buffer pixel k i it stands for (joint_upsample.glsl).
HostImage smooth_low_image(int k, uint32_t width, uint32_t height);

// Mean and largest |image - smooth_value| over a width x height RGBA image's red channel.
struct SmoothError {
  double mean, largest;
};
SmoothError smooth_error(const std::vector<float>& image, uint32_t width, uint32_t height);

// sum |a - b| / sum |b| over the rgb of surface pixels (depth > 0): how far a filter's result
// `a` is from the reference `b`, both RGBA.
double relative_l1_on_surfaces(const std::vector<float>& a, const std::vector<float>& b,
                               const std::vector<float>& depth);

}  // namespace lg::test
