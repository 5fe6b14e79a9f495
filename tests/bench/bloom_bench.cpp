// lumagraph-bench-bloom: post.bloom on lavapipe against the direct convolution with the kernel
// its mip chain stands for (tests/post/bloom_reference.h), on a frame of the gallery world lit
// as examples/post.json lights it (1280x720 by default). post.bloom runs with intensity 1 and
// threshold 0, so that its output is the bloom term itself, its levels swept: its GPU time (the
// fastest frame of --frames, after one that JIT-compiles the pipelines, less the fastest frame
// that only uploads the image; on a machine other jobs load, the fastest frame is the one least
// slowed by them, and lavapipe's per-pass timestamps can put a pass's work on a neighbour's:
// their sum in that frame is printed beside it) and its error,
// the RMS of the difference over the RMS of the reference, on the whole frame and away from
// its borders (--margin pixels in), where the chain's clamped taps and the reference's extended
// edges differ. Prints a table and writes bloom.csv into --results-dir;
// scripts/run-bloom-benchmarks plots it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "runtime/scene/load_world.h"
#include "tests/bench/bench_flags.h"
#include "tests/post/bloom_reference.h"
#include "tests/post/ibl_graph.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  std::string world = "examples/worlds/gallery.json";
  uint32_t width = 1280, height = 720;
  uint32_t frames = 15, margin = 64, max_levels = 8;
};

std::string bloom_graph(uint32_t levels) {
  return R"({ "format": "lumagraph/1", "nodes": [ { "id": "src", "type": "test.image" },
    { "id": "bloom", "type": "post.bloom", "params": { "intensity": 1, "threshold": 0, "levels": )" +
         std::to_string(levels) + R"( } } ],
    "links": [ { "from": "src.color", "to": "bloom.color" } ], "outputs": [ "bloom.color" ] })";
}

// RMS of a - b over RMS of b, rgb of the pixels at least `margin` from every border.
double relative_rms(const std::vector<float>& a, const std::vector<float>& b, uint32_t width, uint32_t height,
                    uint32_t margin) {
  double difference = 0, norm = 0;
  for (uint32_t y = margin; y + margin < height; ++y)
    for (uint32_t x = margin; x + margin < width; ++x)
      for (size_t c = 0; c < 3; ++c) {
        const size_t k = (size_t(y) * width + x) * 4 + c;
        difference += std::pow(double(a[k]) - b[k], 2);
        norm += std::pow(double(b[k]), 2);
      }
  return std::sqrt(difference / norm);
}

// The kernel's standard deviation in pixels (it sums to 1 and is centred).
double deviation(const std::vector<double>& kernel) {
  const double r = double(kernel.size() / 2);
  double variance = 0;
  for (size_t i = 0; i < kernel.size(); ++i) variance += kernel[i] * (double(i) - r) * (double(i) - r);
  return std::sqrt(variance);
}

struct Timing {
  double frame_ms = INFINITY, passes_ms = 0;  // of the fastest frame
};

Timing time_frames(test::ExposureHarness& h, uint32_t frames) {
  Timing fastest;
  for (uint32_t f = 0; f <= frames; ++f) {
    const FrameStats stats = h.run_frame();
    if (f == 0 || stats.gpu_ms >= fastest.frame_ms) continue;  // the first JIT-compiles the pipelines
    fastest = {stats.gpu_ms, 0.0};
    for (const PassStats& p : stats.passes)
      if (p.name.starts_with("bloom/")) fastest.passes_ms += p.gpu_ms;
  }
  return fastest;
}

double total(const std::vector<float>& rgba) {
  double sum = 0;
  for (size_t k = 0; k < rgba.size(); ++k)
    if (k % 4 != 3) sum += rgba[k];
  return sum;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  using namespace lg;
  bench::Options o;
  bench::BenchFlags flags(
      "usage: lumagraph-bench-bloom [--results-dir DIR] [--world FILE] [--size WxH] [--frames N] [--margin PX]\n"
      "                             [--max-levels N]\n");
  flags.text("--results-dir", o.results_dir);
  flags.text("--world", o.world);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames);
  flags.count("--margin", o.margin, 0);
  flags.count("--max-levels", o.max_levels);
  if (const auto status = flags.parse(argc, argv)) return *status;
  std::filesystem::create_directories(o.results_dir);

  RendererOptions options;
  options.device.validation = false;  // timings of the driver; the tests run these passes with it
  options.alias = false;
  Renderer renderer(options);
  renderer.set_graph(test::ibl_graph());
  renderer.render(load_world(o.world), {o.width, o.height});
  const test::HostImage frame{o.width, o.height, renderer.executor().read_image("ibl.color")};
  std::printf("post.bloom on a frame of %s, %ux%u (intensity 1, threshold 0)\n", o.world.c_str(), o.width, o.height);

  std::FILE* csv = std::fopen((o.results_dir + "/bloom.csv").c_str(), "w");
  test::ExposureHarness upload(renderer.context(),
                               R"({ "format": "lumagraph/1", "nodes": [ { "id": "src", "type": "test.image" } ],
    "outputs": [ "src.color" ] })",
                               frame);
  const double upload_ms = bench::time_frames(upload, o.frames).frame_ms;
  std::printf("the frame that only uploads the image takes %.1f ms\n", upload_ms);
  std::fprintf(csv, "levels,kernel_radius,kernel_sigma,bloom_ms,passes_ms,error,error_inside,total_ratio\n");
  std::printf("radius and sigma: of the deepest level's kernel, pixels\n");
  std::printf("%6s %8s %8s %9s %10s %10s %10s %10s\n", "levels", "radius", "sigma", "bloom ms", "passes ms", "error",
              "inside", "total");
  test::HostImage sum = frame;  // the per-level convolutions, summed as the levels grow
  std::fill(sum.rgba.begin(), sum.rgba.end(), 0.0f);
  for (uint32_t levels = 1; levels <= o.max_levels; ++levels) {
    const std::vector<double> kernel = test::bloom_level_kernel(levels - 1);
    const test::HostImage level = test::convolve_separable(frame, kernel);
    for (size_t k = 0; k < sum.rgba.size(); ++k) sum.rgba[k] += level.rgba[k];
    std::vector<float> reference = sum.rgba;
    for (float& v : reference) v /= float(levels);

    test::ExposureHarness h(renderer.context(), bench::bloom_graph(levels), frame);
    const bench::Timing timing = bench::time_frames(h, o.frames);
    const double bloom_ms = timing.frame_ms - upload_ms;
    const std::vector<float> gpu = h.executor().read_image("bloom.color");
    const double e = bench::relative_rms(gpu, reference, o.width, o.height, 0);
    const double inside = bench::relative_rms(gpu, reference, o.width, o.height, o.margin);
    const double ratio = bench::total(gpu) / bench::total(reference);
    const double sigma = bench::deviation(kernel);
    std::printf("%6u %8zu %8.2f %9.1f %10.1f %10.5f %10.5f %10.5f\n", levels, kernel.size() / 2, sigma, bloom_ms,
                timing.passes_ms, e, inside, ratio);
    std::fprintf(csv, "%u,%zu,%.3f,%.3f,%.3f,%.6f,%.6f,%.6f\n", levels, kernel.size() / 2, sigma, bloom_ms,
                 timing.passes_ms, e, inside, ratio);
    std::fflush(stdout);
  }
  std::fclose(csv);
  std::printf("wrote bloom.csv in %s\n", o.results_dir.c_str());
}
