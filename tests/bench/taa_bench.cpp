// lumagraph-bench-taa: post.taa on lavapipe against the supersampled reference (the same frame
// at --samples Halton (2, 3) jitter positions, averaged; tests/post/taa_support.h) on the default
// world, lit by lighting.deferred:
//   still camera   TAA's error frame by frame against the unjittered frame's, and its flicker
//                  (mean |frame - previous frame| once converged, the second half of --frames);
//   moving camera  the camera sliding sideways --step metres a frame for --path-frames frames,
//                  each frame with its own reference: error and crawl (how much a frame's error
//                  changed since the previous frame's) of TAA and of the unjittered frame;
//   pass times     taa/resolve and taa/sharpen at --timing-size, median of the frames after the
//                  first, validation off.
// Measures work on radiance compressed as x / (1 + x). Prints tables and writes taa_still.csv,
// taa_moving.csv and taa_summary.csv into --results-dir (scripts/run-taa-benchmarks plots them).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "runtime/scene/default_world.h"
#include "tests/bench/bench_flags.h"
#include "tests/post/taa_support.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 160, height = 90;
  uint32_t frames = 64, path_frames = 24, samples = 64;
  std::vector<double> step{0.01};  // metres a frame, sideways
  uint32_t timing_width = 1280, timing_height = 720;
  uint32_t timing_frames = 6;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

double pass_ms(const FrameStats& stats, const std::string& name) {
  for (const PassStats& p : stats.passes)
    if (p.name == name) return p.gpu_ms;
  return 0.0;
}

struct StillResult {
  double unjittered_error = 0, taa_error = 0, taa_flicker = 0;
};

StillResult still_camera(const Options& o, std::ofstream& csv) {
  const World world = default_world();
  const FrameSize size{o.width, o.height};
  Renderer renderer(test::taa_renderer_options(false));
  const std::vector<float> reference = test::supersampled_reference(renderer, world, size, o.samples);
  renderer.render(world, size);
  StillResult r;
  r.unjittered_error = test::compressed_rms_error(renderer.executor().read_image("light.color"), reference);
  renderer.set_graph(test::taa_test_graph(true));
  std::vector<float> previous;
  std::vector<double> flicker;
  std::printf("\nstill camera, %ux%u, reference %u samples: error per frame\n%6s %12s %12s\n", o.width, o.height,
              o.samples, "frame", "taa", "unjittered");
  for (uint32_t frame = 0; frame < o.frames; ++frame) {
    renderer.render(world, size);
    std::vector<float> taa = renderer.executor().read_image("taa.color");
    r.taa_error = test::compressed_rms_error(taa, reference);
    if (frame >= o.frames / 2 && !previous.empty())
      flicker.push_back(test::compressed_mean_abs_difference(taa, previous));
    csv << frame << ',' << r.taa_error << ',' << r.unjittered_error << '\n';
    if (frame % 8 == 0 || frame + 1 == o.frames)
      std::printf("%6u %12.6f %12.6f\n", frame, r.taa_error, r.unjittered_error);
    previous = std::move(taa);
  }
  for (double f : flicker) r.taa_flicker += f / double(flicker.size());
  return r;
}

struct MovingResult {
  double taa_error = 0, unjittered_error = 0, taa_crawl = 0, unjittered_crawl = 0;
};

// Frame 0 is left out of the means: TAA has no history yet, and there is no previous error.
MovingResult moving_camera(const Options& o, double step, std::ofstream& csv) {
  World world = default_world();
  const FrameSize size{o.width, o.height};
  Renderer taa(test::taa_renderer_options(false)), plain(test::taa_renderer_options(false));
  taa.set_graph(test::taa_test_graph(true));
  std::vector<float> previous_taa, previous_plain, previous_reference;
  MovingResult r;
  std::printf("\nmoving camera, %.4f m a frame sideways, %ux%u\n%6s %12s %12s %12s %12s\n", step, o.width, o.height,
              "frame", "taa error", "plain error", "taa crawl", "plain crawl");
  for (uint32_t frame = 0; frame < o.path_frames; ++frame) {
    if (frame > 0) test::move_camera(world, {float(step), 0.0f, 0.0f});
    taa.render(world, size);
    std::vector<float> t = taa.executor().read_image("taa.color");
    std::vector<float> reference = test::supersampled_reference(plain, world, size, o.samples);
    plain.render(world, size);  // the same graph, unjittered
    std::vector<float> u = plain.executor().read_image("light.color");
    const double te = test::compressed_rms_error(t, reference), ue = test::compressed_rms_error(u, reference);
    double tc = 0, uc = 0;
    if (frame > 0) {
      tc = test::aliasing_crawl(t, reference, previous_taa, previous_reference);
      uc = test::aliasing_crawl(u, reference, previous_plain, previous_reference);
      const double n = double(o.path_frames - 1);
      r.taa_error += te / n, r.unjittered_error += ue / n, r.taa_crawl += tc / n, r.unjittered_crawl += uc / n;
    }
    csv << step << ',' << frame << ',' << te << ',' << ue << ',' << tc << ',' << uc << '\n';
    std::printf("%6u %12.6f %12.6f %12.6f %12.6f\n", frame, te, ue, tc, uc);
    previous_taa = std::move(t), previous_plain = std::move(u), previous_reference = std::move(reference);
  }
  return r;
}

void pass_times(const Options& o, double& resolve_ms, double& sharpen_ms, double& light_ms) {
  const World world = default_world();
  Renderer renderer(test::taa_renderer_options(false));
  renderer.set_graph(test::taa_test_graph(true, R"({ "sharpen": 0.3 })"));
  std::vector<double> resolve, sharpen, light;
  for (uint32_t frame = 0; frame < o.timing_frames; ++frame) {
    const FrameStats stats = renderer.render(world, {o.timing_width, o.timing_height});
    if (frame == 0) continue;  // JIT-compiles the pipelines
    resolve.push_back(pass_ms(stats, "taa/resolve"));
    sharpen.push_back(pass_ms(stats, "taa/sharpen"));
    double lighting = 0;  // every pass of lighting.deferred
    for (const PassStats& p : stats.passes)
      if (p.name.starts_with("light/")) lighting += p.gpu_ms;
    light.push_back(lighting);
  }
  resolve_ms = median(resolve), sharpen_ms = median(sharpen), light_ms = median(light);
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  using namespace lg::bench;
  Options o;
  BenchFlags flags(
      "usage: lumagraph-bench-taa [--results-dir DIR] [--size WxH] [--frames N] [--path-frames N] [--samples N]\n"
      "                           [--step M,...] [--timing-size WxH] [--timing-frames N]");
  flags.text("--results-dir", o.results_dir);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames, 4);
  flags.count("--path-frames", o.path_frames, 2);
  flags.count("--samples", o.samples);
  flags.numbers("--step", o.step);
  flags.size("--timing-size", o.timing_width, o.timing_height);
  flags.count("--timing-frames", o.timing_frames, 2);
  if (const auto status = flags.parse(argc, argv)) return *status;
  std::filesystem::create_directories(o.results_dir);
  const std::filesystem::path dir(o.results_dir);

  std::ofstream still_csv(dir / "taa_still.csv");
  still_csv << "frame,taa_error,unjittered_error\n";
  const StillResult still = still_camera(o, still_csv);
  std::ofstream moving_csv(dir / "taa_moving.csv");
  moving_csv << "step_m,frame,taa_error,unjittered_error,taa_crawl,unjittered_crawl\n";
  std::vector<MovingResult> moving;
  for (double step : o.step) moving.push_back(moving_camera(o, step, moving_csv));
  double resolve_ms = 0, sharpen_ms = 0, light_ms = 0;
  pass_times(o, resolve_ms, sharpen_ms, light_ms);

  std::ofstream summary(dir / "taa_summary.csv");
  summary << "measure,value\n";
  auto row = [&](const std::string& name, double value, const char* format) {
    summary << name << ',' << value << '\n';
    std::printf(("%-44s " + std::string(format) + "\n").c_str(), name.c_str(), value);
  };
  std::printf("\nsummary (errors and differences on x / (1 + x) radiance)\n");
  row("still: unjittered error", still.unjittered_error, "%.6f");
  row("still: taa error, last frame", still.taa_error, "%.6f");
  row("still: taa error / unjittered error", still.taa_error / still.unjittered_error, "%.3f");
  row("still: taa flicker (converged)", still.taa_flicker, "%.6f");
  for (size_t i = 0; i < moving.size(); ++i) {
    const std::string at = "moving " + std::to_string(o.step[i]).substr(0, 6) + " m/frame: ";
    row(at + "taa error", moving[i].taa_error, "%.6f");
    row(at + "unjittered error", moving[i].unjittered_error, "%.6f");
    row(at + "taa crawl", moving[i].taa_crawl, "%.6f");
    row(at + "unjittered crawl", moving[i].unjittered_crawl, "%.6f");
    row(at + "still taa flicker / unjittered crawl", still.taa_flicker / moving[i].unjittered_crawl, "%.3f");
  }
  const std::string at = std::to_string(o.timing_width) + "x" + std::to_string(o.timing_height) + ": ";
  row(at + "taa/resolve ms", resolve_ms, "%.3f");
  row(at + "taa/sharpen ms", sharpen_ms, "%.3f");
  row(at + "lighting.deferred ms", light_ms, "%.3f");
  std::printf("wrote taa_still.csv, taa_moving.csv and taa_summary.csv in %s\n", o.results_dir.c_str());
}
