#include "tests/post/taa_support.h"

#include <cmath>
#include <stdexcept>

#include "graph/graph_io.h"
#include "runtime/scene/camera_jitter.h"

namespace lg::test {
namespace {

float compressed(float x) {
  return x / (1.0f + x);
}

void check_same_size(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.size() % 4 != 0)
    throw std::invalid_argument("taa support: images of " + std::to_string(a.size()) + " and " +
                                std::to_string(b.size()) + " floats cannot be compared");
}

}  // namespace

Graph taa_test_graph(bool taa, const std::string& taa_params) {
  const std::string text = taa ? R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "light", "type": "lighting.deferred", "params": { "shadow_map_size": 512 } },
      { "id": "taa", "type": "post.taa", "params": )" +
                                     taa_params + R"( } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "light.gbuffer" }, { "from": "gbuf.gbuffer", "to": "taa.gbuffer" },
               { "from": "light.color", "to": "taa.color" }, { "from": "taa.accumulated", "to": "taa.history" } ],
    "outputs": [ "taa.color", "light.color" ] })"
                               : R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "light", "type": "lighting.deferred", "params": { "shadow_map_size": 512 } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "light.gbuffer" } ],
    "outputs": [ "light.color" ] })";
  Diagnostics d("taa-test.json");
  std::optional<Graph> graph = parse_graph_text(text, d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

RendererOptions taa_renderer_options(bool validation) {
  RendererOptions options;
  options.device.validation = validation;
  options.alias = false;
  return options;
}

std::vector<float> supersampled_reference(Renderer& renderer, const World& world, FrameSize size, uint32_t samples) {
  renderer.set_graph(taa_test_graph(false));
  std::vector<double> sum;
  for (uint32_t i = 0; i < samples; ++i) {
    renderer.render(world, size, {.jitter = halton_jitter_pixels(i)});
    const std::vector<float> frame = renderer.executor().read_image("light.color");
    sum.resize(frame.size(), 0.0);
    for (size_t k = 0; k < frame.size(); ++k) sum[k] += frame[k];
  }
  std::vector<float> mean(sum.size());
  for (size_t k = 0; k < sum.size(); ++k) mean[k] = float(sum[k] / samples);
  return mean;
}

double compressed_rms_error(const std::vector<float>& image, const std::vector<float>& reference) {
  check_same_size(image, reference);
  double sum = 0.0;
  for (size_t k = 0; k < image.size(); ++k) {
    if (k % 4 == 3) continue;
    const double d = compressed(image[k]) - compressed(reference[k]);
    sum += d * d;
  }
  return std::sqrt(sum / double(image.size() / 4 * 3));
}

double compressed_mean_abs_difference(const std::vector<float>& a, const std::vector<float>& b) {
  check_same_size(a, b);
  double sum = 0.0;
  for (size_t k = 0; k < a.size(); ++k)
    if (k % 4 != 3) sum += std::abs(double(compressed(a[k])) - compressed(b[k]));
  return sum / double(a.size() / 4 * 3);
}

double aliasing_crawl(const std::vector<float>& frame, const std::vector<float>& reference,
                      const std::vector<float>& previous, const std::vector<float>& previous_reference) {
  check_same_size(frame, reference);
  check_same_size(previous, previous_reference);
  check_same_size(frame, previous);
  double sum = 0.0;
  for (size_t k = 0; k < frame.size(); ++k) {
    if (k % 4 == 3) continue;
    const double now = double(compressed(frame[k])) - compressed(reference[k]);
    const double before = double(compressed(previous[k])) - compressed(previous_reference[k]);
    sum += std::abs(now - before);
  }
  return sum / double(frame.size() / 4 * 3);
}

void move_camera(World& world, glm::vec3 offset) {
  world.get<Transform>(world.active_camera).position += offset;
}

}  // namespace lg::test
