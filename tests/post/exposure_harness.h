// Running post.exposure (and post.tonemap after it) on an image the test holds: a test-only
// node, test.image, copies that image into its output every frame, so a graph of built-in
// post nodes can be fed a real HDR file or a synthetic image and run frame after frame. Shared
// by the exposure tests and its benchmark, and by the bilateral and upsample tests, which put a
// world in scene() for scene.gbuffer to draw.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/compiler.h"
#include "graph/scene_summary.h"
#include "runtime/exec/executor.h"
#include "runtime/exec/frame_stats.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/scene/scene_view.h"

namespace lg::test {

struct HostImage {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats a pixel, row by row
};

// A graph of the built-in nodes plus test.image (id "src", the frame's size, output
// "src.color") compiled without aliasing (every resource stays readable) and run by an executor.
class ExposureHarness {
 public:
  // `graph_json`: a graph file's text that may use "test.image"; the frame is `image`'s size
  // unless `frame` says (test.image's "scale" param then sizes the image against it). The plan
  // is compiled for `scene` (the summary decides bypasses: a thin-lens camera for post.dof).
  ExposureHarness(Context& context, std::string_view graph_json, HostImage image,
                  std::optional<FrameSize> frame = std::nullopt, const SceneSummary& scene = default_scene_summary());

  HostImage& image() { return *image_; }  // change it between frames
  SceneView& scene() { return scene_; }   // frame_seconds, camera_cut
  Executor& executor() { return *executor_; }
  FrameStats run_frame();
  // The first texel's red channel of a resource ("exposure.exposure").
  float read_scalar(std::string_view resource);

 private:
  std::shared_ptr<HostImage> image_;
  KernelRegistry kernels_;
  SceneView scene_;
  GpuScene gpu_scene_;
  std::unique_ptr<Executor> executor_;
};

// A graph text with test.image "src" feeding post.exposure "exposure" (params as a JSON object's
// text), its history linked back when `history`, and its exposure output a result.
std::string exposure_graph(std::string_view params = "{}", bool history = true);

// The HDR file's pixels; throws naming the file.
HostImage load_host_image(const std::string& path);

}  // namespace lg::test
