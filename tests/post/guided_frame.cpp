#include "tests/post/guided_frame.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg::test {

std::string guided_graph(std::string_view node, double image_scale, double gbuffer_scale) {
  return R"({ "format": "lumagraph/1", "nodes": [
    { "id": "src", "type": "test.image", "params": { "scale": )" +
         std::to_string(image_scale) + R"( } },
    { "id": "gbuf", "type": "scene.gbuffer", "params": { "resolution_scale": )" +
         std::to_string(gbuffer_scale) + " } }, " + std::string(node) + R"( ],
    "links": [ { "from": "src.color", "to": "node.color" }, { "from": "gbuf.gbuffer", "to": "node.gbuffer" } ],
    "outputs": [ "node.color" ] })";
}

void show_cornell_box(ExposureHarness& h, uint32_t frame_width, uint32_t frame_height) {
  // The view shares the world's meshes: the world lives as long as the tests.
  static const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  h.scene() = make_scene_view(world, float(frame_width) / float(frame_height));
}

std::string frame_error(ExposureHarness& h) {
  try {
    h.run_frame();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

std::vector<float> gbuffer_depth(ExposureHarness& h) {
  const std::vector<float> texels = h.executor().read_image("gbuf.gbuffer.depth");
  std::vector<float> depth;
  for (size_t i = 0; i < texels.size(); i += 4) depth.push_back(texels[i]);
  return depth;
}

Guide cornell_box_guide(Context& context, uint32_t width, uint32_t height) {
  const float one[4] = {1, 1, 1, 1};
  ExposureHarness h(context, guided_graph(R"({ "id": "node", "type": "post.bilateral", "params": { "radius": 1 } })"),
                    constant_image(width, height, one));
  show_cornell_box(h, width, height);
  h.run_frame();
  return {gbuffer_depth(h), h.scene().camera.near_plane};
}

HostImage constant_image(uint32_t width, uint32_t height, const float (&rgba)[4]) {
  HostImage image{width, height, std::vector<float>(size_t{width} * height * 4)};
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = rgba[i % 4];
  return image;
}

HostImage distance_image(const std::vector<float>& depth, float near_plane, uint32_t width, uint32_t height,
                         float noise, unsigned seed) {
  const float one[4] = {1, 1, 1, 1};
  HostImage image = constant_image(width, height, one);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> factor(1.0f - noise, 1.0f + noise);
  for (size_t i = 0; i < depth.size(); ++i)
    if (depth[i] > 0.0f)
      for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = near_plane / depth[i] * (noise > 0 ? factor(rng) : 1.0f);
  return image;
}

double smooth_value(double x, double y, uint32_t width, uint32_t height) {
  const double fx = 2 * std::numbers::pi * 1.5 / width, fy = 2 * std::numbers::pi / height;
  return 1.5 + 0.25 * std::sin(fx * x + 0.3) + 0.25 * std::cos(fy * y + 0.7);
}

Slope smooth_slope(uint32_t width, uint32_t height) {
  return {0.25 * 2 * std::numbers::pi * 1.5 / width, 0.25 * 2 * std::numbers::pi / height};
}

HostImage smooth_low_image(int k, uint32_t width, uint32_t height) {
  const uint32_t w = width / uint32_t(k), h = height / uint32_t(k);
  HostImage low{w, h, std::vector<float>(size_t{w} * h * 4, 1.0f)};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        low.rgba[4 * (size_t(y) * w + x) + c] = float(smooth_value(double(k * x), double(k * y), width, height));
  return low;
}

SmoothError smooth_error(const std::vector<float>& image, uint32_t width, uint32_t height) {
  double sum = 0, largest = 0;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const double error = std::abs(image[4 * (size_t(y) * width + x)] - smooth_value(x, y, width, height));
      sum += error;
      largest = std::max(largest, error);
    }
  return {sum / double(size_t{width} * height), largest};
}

double relative_l1_on_surfaces(const std::vector<float>& a, const std::vector<float>& b,
                               const std::vector<float>& depth) {
  double difference = 0, total = 0;
  for (size_t i = 0; i < depth.size(); ++i)
    if (depth[i] > 0.0f)
      for (int c = 0; c < 3; ++c) {
        difference += std::abs(double(a[4 * i + c]) - double(b[4 * i + c]));
        total += std::abs(double(b[4 * i + c]));
      }
  return total > 0 ? difference / total : 0;
}

}  // namespace lg::test
