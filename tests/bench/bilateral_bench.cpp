// lumagraph-bench-bilateral: post.bilateral and post.upsample on lavapipe at 1280x720 over the
// Cornell box's G-buffer (tests/post/guided_frame.h). The bilateral filter's radius is swept
// (sigma_spatial = radius / 2) for the full kernel and the separable form: the GPU time of the
// node's passes (fastest and median of --frames frames after one that JIT-compiles the
// pipelines) and the separable form's error against the full kernel (relative L1 over surface
// pixels) on the noisy distance image. post.upsample at k = 2 and 4: its pass time and its
// error on a smooth function. Prints tables and writes bilateral.csv and upsample.csv into
// --results-dir; scripts/run-bilateral-benchmarks plots them.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime/gpu/context.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/node_pass_timing.h"
#include "tests/post/guided_frame.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 1280, height = 720;
  int frames = 5;
  std::vector<double> radii = {1, 2, 4, 8};
};

std::string bilateral_node(const char* kernel, int radius) {
  return R"({ "id": "node", "type": "post.bilateral", "params": { "kernel": ")" + std::string(kernel) +
         R"(", "radius": )" + std::to_string(radius) + R"(, "sigma_spatial": )" + std::to_string(0.5 * radius) + " } }";
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  using namespace lg;
  bench::Options o;
  bench::BenchFlags flags(
      "usage: lumagraph-bench-bilateral [--results-dir DIR] [--size WxH] [--frames N] [--radii R,R,...]\n");
  flags.text("--results-dir", o.results_dir);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames);
  flags.numbers("--radii", o.radii);
  if (const auto status = flags.parse(argc, argv)) return *status;
  std::filesystem::create_directories(o.results_dir);

  // No validation layer: the timings are of the driver (the tests run the same passes with it).
  Context context{ContextOptions{}};
  const test::Guide guide = test::cornell_box_guide(context, o.width, o.height);
  const test::HostImage image = test::distance_image(guide.depth, guide.near_plane, o.width, o.height, 0.5f, 1);

  std::FILE* csv = std::fopen((o.results_dir + "/bilateral.csv").c_str(), "w");
  std::fprintf(csv, "radius,full_fastest_ms,full_median_ms,separable_fastest_ms,separable_median_ms,separable_error\n");
  std::printf("post.bilateral, %ux%u, Cornell box, noisy distance image\n", o.width, o.height);
  std::printf("%6s %22s %22s %16s\n", "radius", "full ms (fast/median)", "separable ms", "separable error");
  for (const double r : o.radii) {
    const int radius = int(r);
    std::vector<float> result[2];
    bench::Timing timing[2];
    const char* kernels[2] = {"full", "separable"};
    for (int k = 0; k < 2; ++k) {
      test::ExposureHarness h(context, test::guided_graph(bench::bilateral_node(kernels[k], radius)), image);
      test::show_cornell_box(h, o.width, o.height);
      timing[k] = bench::time_node(h, o.frames, "node/");
      result[k] = h.executor().read_image("node.color");
    }
    const double error = test::relative_l1_on_surfaces(result[1], result[0], guide.depth);
    std::printf("%6d %10.1f / %-9.1f %10.1f / %-9.1f %16.5f\n", radius, timing[0].fastest_ms, timing[0].median_ms,
                timing[1].fastest_ms, timing[1].median_ms, error);
    std::fprintf(csv, "%d,%.3f,%.3f,%.3f,%.3f,%.6f\n", radius, timing[0].fastest_ms, timing[0].median_ms,
                 timing[1].fastest_ms, timing[1].median_ms, error);
  }
  std::fclose(csv);

  csv = std::fopen((o.results_dir + "/upsample.csv").c_str(), "w");
  std::fprintf(csv, "k,fastest_ms,median_ms,mean_error,largest_error\n");
  std::printf("\npost.upsample to %ux%u, Cornell box, smooth function in [1, 2]\n", o.width, o.height);
  std::printf("%3s %22s %12s %12s\n", "k", "ms (fastest/median)", "mean error", "largest");
  for (const int k : {2, 4}) {
    // The frame is the G-buffer's size; test.image at 1/k of it.
    test::ExposureHarness h(context, test::guided_graph(R"({ "id": "node", "type": "post.upsample" })", 1.0 / k),
                            test::smooth_low_image(k, o.width, o.height), FrameSize{o.width, o.height});
    test::show_cornell_box(h, o.width, o.height);
    const bench::Timing t = bench::time_node(h, o.frames, "node/");
    const test::SmoothError e = test::smooth_error(h.executor().read_image("node.color"), o.width, o.height);
    std::printf("%3d %10.2f / %-9.2f %12.5f %12.5f\n", k, t.fastest_ms, t.median_ms, e.mean, e.largest);
    std::fprintf(csv, "%d,%.3f,%.3f,%.6f,%.6f\n", k, t.fastest_ms, t.median_ms, e.mean, e.largest);
  }
  std::fclose(csv);
  std::printf("wrote %s/bilateral.csv and upsample.csv\n", o.results_dir.c_str());
}
