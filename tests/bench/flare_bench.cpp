// lumagraph-bench-flare: post.flare on lavapipe at 1280x720 with its quality knob, the grid's
// resolution_scale (1, 1/2, 1/4, 1/8), swept: the GPU time of the node's passes (fastest and
// median of --frames frames after one that JIT-compiles the pipelines) and the error of the
// added flare against the reference. Lens flare has no physical ground truth here: the reference
// is the node's stated model (nodes/post/flare/flare_model.h) evaluated on the CPU in double
// precision at full resolution (resolution_scale 1). Columns: the GPU's error, the model's own
// at that scale (what the coarser grid loses), and the GPU against the model at that scale.
// The image: the Grace Cathedral probe (../shared/data/env/grace.hdr) stretched bilinearly to
// the frame, whose windows and lamps are the bright pixels. Prints a table and writes flare.csv
// into --results-dir; scripts/run-flare-benchmarks plots it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "nodes/post/flare/flare_model.h"
#include "runtime/gpu/context.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/node_pass_timing.h"
#include "tests/post/exposure_harness.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  std::string image = "../shared/data/env/grace.hdr";
  uint32_t width = 1280, height = 720;
  int frames = 5;
  std::vector<double> scales = {1, 0.5, 0.25, 0.125};
};

test::HostImage stretched(const test::HostImage& source, uint32_t width, uint32_t height) {
  test::HostImage out{width, height, std::vector<float>(size_t{width} * height * 4, 1.0f)};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const double sx = std::clamp((x + 0.5) * source.width / width - 0.5, 0.0, source.width - 1.0);
      const double sy = std::clamp((y + 0.5) * source.height / height - 0.5, 0.0, source.height - 1.0);
      const uint32_t x0 = uint32_t(sx), y0 = uint32_t(sy);
      const uint32_t x1 = std::min(x0 + 1, source.width - 1), y1 = std::min(y0 + 1, source.height - 1);
      const double fx = sx - x0, fy = sy - y0;
      auto at = [&](uint32_t px, uint32_t py, int k) { return source.rgba[(size_t(py) * source.width + px) * 4 + k]; };
      for (int k = 0; k < 3; ++k)
        out.rgba[(size_t(y) * width + x) * 4 + size_t(k)] =
            float((1 - fy) * ((1 - fx) * at(x0, y0, k) + fx * at(x1, y0, k)) +
                  fy * ((1 - fx) * at(x0, y1, k) + fx * at(x1, y1, k)));
    }
  return out;
}

// Relative L1 of `image`'s flare (image - input) against `reference`'s, over rgb. With
// `rounded`, `image` is the GPU's rgba16f output: each value's difference less its own rounding
// (2^-11 of it), which on the probe's bright background is larger than much of the flare.
double flare_error(const std::vector<float>& image, const std::vector<float>& reference,
                   const std::vector<float>& input, bool rounded) {
  double difference = 0, total = 0;
  for (size_t i = 0; i < input.size(); i += 4)
    for (size_t k = 0; k < 3; ++k) {
      const double want = double(reference[i + k]) - input[i + k];
      const double rounding = rounded ? std::abs(image[i + k]) * std::exp2(-11) : 0;
      difference += std::max(0.0, std::abs(double(image[i + k]) - input[i + k] - want) - rounding);
      total += std::abs(want);
    }
  return total > 0 ? difference / total : 0;
}

std::string flare_graph(double scale) {
  return R"({ "format": "lumagraph/1", "nodes": [ { "id": "src", "type": "test.image" },
    { "id": "flare", "type": "post.flare", "params": { "resolution_scale": )" +
         std::to_string(scale) + R"( } } ], "links": [ { "from": "src.color", "to": "flare.color" } ],
    "outputs": [ "flare.color", "src.color" ] })";
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  using namespace lg;
  bench::Options o;
  bench::BenchFlags flags(
      "usage: lumagraph-bench-flare [--results-dir DIR] [--image FILE.hdr] [--size WxH] [--frames N] "
      "[--scales S,S,...]\n");
  flags.text("--results-dir", o.results_dir);
  flags.text("--image", o.image);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames);
  flags.numbers("--scales", o.scales);
  if (const auto status = flags.parse(argc, argv)) return *status;
  std::filesystem::create_directories(o.results_dir);

  // No validation layer: the timings are of the driver (the tests run the same passes with it).
  Context context{ContextOptions{}};
  const test::HostImage image = bench::stretched(test::load_host_image(o.image), o.width, o.height);

  // The reference: the model at full resolution on what the GPU reads (the image in rgba16f).
  std::vector<float> input, reference;
  {
    test::ExposureHarness h(context, bench::flare_graph(1), image);
    h.run_frame();
    input = h.executor().read_image("src.color");
    FlareSettings full;
    full.divisor = 1;
    reference = evaluate_flare(input, o.width, o.height, full).rgba;
  }

  std::FILE* csv = std::fopen((o.results_dir + "/flare.csv").c_str(), "w");
  std::fprintf(csv, "resolution_scale,fastest_ms,median_ms,error,model_error,gpu_model_error,guard\n");
  std::printf("post.flare (default params), %ux%u, %s stretched\n", o.width, o.height, o.image.c_str());
  std::printf("%16s %22s %10s %12s %12s %8s\n", "resolution_scale", "GPU ms (fast/median)", "error", "model error",
              "GPU-model", "guard");
  for (const double scale : o.scales) {
    test::ExposureHarness h(context, bench::flare_graph(scale), image);
    const bench::Timing t = bench::time_node(h, o.frames, "flare/");
    const std::vector<float> out = h.executor().read_image("flare.color");
    FlareSettings s;
    s.divisor = int(std::lround(1 / scale));
    const FlareResult model = evaluate_flare(input, o.width, o.height, s);
    const double error = bench::flare_error(out, reference, input, true);
    const double model_error = bench::flare_error(model.rgba, reference, input, false);
    const double gpu_model_error = bench::flare_error(out, model.rgba, input, true);
    std::printf("%16g %10.2f / %9.2f %10.4f %12.4f %12.4f %8.4f\n", scale, t.fastest_ms, t.median_ms, error,
                model_error, gpu_model_error, model.guard);
    std::fprintf(csv, "%g,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f\n", scale, t.fastest_ms, t.median_ms, error, model_error,
                 gpu_model_error, model.guard);
  }
  std::fclose(csv);
  return 0;
}
