// lumagraph-bench-exposure: post.exposure on lavapipe at 320x180 to 1920x1080 (1280x720 the
// reference size) on the HDR images of ../shared/data/env, stretched to each size by nearest
// texel: the GPU time of its two passes (the median of --runs frames after one discarded frame
// that JIT-compiles the pipelines) and the error of its exposure factor against the CPU
// histogram's (exposure_metering.h). Prints a table and writes exposure.csv in the current folder.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "nodes/post/exposure/exposure_metering.h"
#include "runtime/gpu/context.h"
#include "tests/post/exposure_harness.h"

namespace lg::bench {
namespace {

struct Size {
  uint32_t width, height;
};
constexpr Size kSizes[] = {{320, 180}, {640, 360}, {1280, 720}, {1920, 1080}};

test::HostImage stretched(const test::HostImage& image, Size size) {
  test::HostImage out{size.width, size.height, std::vector<float>(size_t{size.width} * size.height * 4)};
  for (uint32_t y = 0; y < size.height; ++y)
    for (uint32_t x = 0; x < size.width; ++x) {
      const size_t from = (size_t{y * image.height / size.height} * image.width + x * image.width / size.width) * 4;
      std::copy_n(image.rgba.begin() + long(from), 4, out.rgba.begin() + (size_t{y} * size.width + x) * 4);
    }
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double pass_ms(const FrameStats& stats, const std::string& name) {
  for (const PassStats& p : stats.passes)
    if (p.name == name) return p.gpu_ms;
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  using namespace lg;
  int runs = 9;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--runs=", 7) == 0) runs = std::max(1, std::atoi(argv[i] + 7));
  // No validation layer: the timings are of the driver (the tests run the same passes with it).
  Context context{ContextOptions{}};
  std::FILE* csv = std::fopen("exposure.csv", "w");
  std::fprintf(csv, "image,width,height,histogram_ms,meter_ms,total_ms,gpu_ev,cpu_ev,factor_error\n");
  std::printf("%-10s %11s %12s %9s %9s %10s %10s %12s\n", "image", "size", "histogram", "meter", "total", "GPU EV",
              "CPU EV", "error");
  for (const char* name : {"pisa.hdr", "grace.hdr"}) {
    const test::HostImage file = test::load_host_image(std::string("../shared/data/env/") + name);
    for (bench::Size size : bench::kSizes) {
      test::ExposureHarness h(context, test::exposure_graph("{}", false), bench::stretched(file, size));
      h.run_frame();  // JIT-compiles the pipelines
      std::vector<double> histogram, meter;
      for (int r = 0; r < runs; ++r) {
        const FrameStats stats = h.run_frame();
        histogram.push_back(bench::pass_ms(stats, "exposure/histogram"));
        meter.push_back(bench::pass_ms(stats, "exposure/meter"));
      }
      const ExposureSettings s;
      const double gpu = h.read_scalar("exposure.exposure");
      const double cpu =
          target_exposure(metered_log2_luminance(exposure_histogram(h.executor().read_image("src.color"), s), s), s);
      const double error = std::abs(std::exp2(gpu - cpu) - 1);
      const double hist_ms = bench::median(histogram), meter_ms = bench::median(meter);
      std::printf("%-10s %5ux%-5u %9.3f ms %6.3f ms %7.3f ms %10.5f %10.5f %12.3g\n", name, size.width, size.height,
                  hist_ms, meter_ms, hist_ms + meter_ms, gpu, cpu, error);
      std::fprintf(csv, "%s,%u,%u,%.4f,%.4f,%.4f,%.6f,%.6f,%.3g\n", name, size.width, size.height, hist_ms, meter_ms,
                   hist_ms + meter_ms, gpu, cpu, error);
    }
  }
  std::fclose(csv);
  std::printf("wrote exposure.csv\n");
}
