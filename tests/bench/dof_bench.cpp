// lumagraph-bench-dof: post.dof on lavapipe against the thin-lens ground truth (the mean of
// --lens-samples pinhole renders over the aperture, each re-aimed at the focus plane;
// tests/post/thin_lens_reference.h) on the gallery world at --size, its camera's aperture
// widened to --aperture metres so that the blur reaches 8 pixels (0.24 m at 640x360; the same
// circles in pixels as 0.12 m at 1280x720). post.dof's max_blur is the largest circle of
// confusion in the frame (nothing is clamped) and its samples are swept: its error against the
// reference, RMS of x / (1 + x) radiance over the whole frame, where the circle is under half a
// pixel (in focus) and where it is over two pixels (defocused), and its GPU time at
// --timing-size with the same params: the fastest frame with it less the fastest without it
// (of --frames frames each, interleaved, after one that JIT-compiles the pipelines; on a machine
// other jobs load, the fastest frame is the one least slowed by them), since lavapipe's per-pass
// timestamps can put a pass's work on a neighbour's (their sum for post.dof's passes, in the
// fastest frame, is printed beside it). The pinhole frame's error says what no depth of field at all would cost,
// and the reference at half its samples against itself how far the reference has converged.
// Prints a table and writes dof.csv into --results-dir; scripts/run-dof-benchmarks plots it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime/scene/load_world.h"
#include "tests/bench/bench_flags.h"
#include "tests/post/ibl_graph.h"
#include "tests/post/thin_lens_reference.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  std::string world = "examples/worlds/gallery.json";
  uint32_t width = 640, height = 360;
  uint32_t timing_width = 1280, timing_height = 720;
  uint32_t lens_samples = 128;
  uint32_t frames = 3;
  double aperture = 0.24;
  std::vector<double> samples = {4, 8, 16, 32, 64, 128, 256};
};

double compressed(double x) {
  return x / (1.0 + x);
}

// RMS over the rgb of the pixels `mask` keeps, of the difference of x / (1 + x).
double masked_error(const std::vector<float>& a, const std::vector<float>& b, const std::vector<bool>& mask) {
  double sum = 0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (size_t c = 0; c < 3; ++c) {
      const double d = compressed(a[p * 4 + c]) - compressed(b[p * 4 + c]);
      sum += d * d;
    }
    n += 3;
  }
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

struct Regions {
  std::vector<bool> all, focus, defocused;
  double largest_coc = 0;
};

// Each pixel's circle of confusion from the G-buffer's depth (reversed Z: near / distance).
Regions regions(const std::vector<float>& depth, const Camera& camera, FrameSize frame) {
  Regions r;
  for (size_t p = 0; p < depth.size() / 4; ++p) {
    const double d = depth[p * 4];
    const double coc = test::coc_radius_pixels(camera, frame, d > 0 ? camera.near_plane / d : INFINITY);
    r.all.push_back(true);
    r.focus.push_back(coc < 0.5);
    r.defocused.push_back(coc > 2.0);
    r.largest_coc = std::max(r.largest_coc, coc);
  }
  return r;
}

double share(const std::vector<bool>& mask) {
  return double(std::count(mask.begin(), mask.end(), true)) / double(mask.size());
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  using namespace lg;
  bench::Options o;
  bench::BenchFlags flags(
      "usage: lumagraph-bench-dof [--results-dir DIR] [--world FILE] [--size WxH] [--timing-size WxH]\n"
      "                           [--lens-samples N] [--frames N] [--aperture M] [--samples N,N,...]\n");
  flags.text("--results-dir", o.results_dir);
  flags.text("--world", o.world);
  flags.size("--size", o.width, o.height);
  flags.size("--timing-size", o.timing_width, o.timing_height);
  flags.count("--lens-samples", o.lens_samples, 2);
  flags.count("--frames", o.frames);
  std::vector<double> aperture{o.aperture};
  flags.numbers("--aperture", aperture);
  flags.numbers("--samples", o.samples);
  if (const auto status = flags.parse(argc, argv)) return *status;
  o.aperture = aperture.at(0);
  std::filesystem::create_directories(o.results_dir);

  World world = load_world(o.world);
  Camera& camera = world.get<Camera>(world.active_camera);
  camera.aperture = float(o.aperture);
  const FrameSize frame{o.width, o.height};

  RendererOptions options;
  options.device.validation = false;  // timings of the driver; the tests run these passes with it
  options.alias = false;
  Renderer renderer(options), timing(options), plain(options);
  plain.set_graph(test::ibl_graph());
  // The fastest frame's GPU time of o.frames after the first, with post.dof (and its passes'
  // times in that frame) and without it, the two renderers' frames interleaved so that both
  // meet the same load.
  struct Timing {
    double with_ms = INFINITY, without_ms = INFINITY, passes_ms = 0;
  };
  auto time_frames = [&] {
    Timing t;
    for (uint32_t f = 0; f <= o.frames; ++f) {
      const FrameStats without = plain.render(world, {o.timing_width, o.timing_height});
      const FrameStats with = timing.render(world, {o.timing_width, o.timing_height});
      if (f == 0) continue;  // JIT-compiles the pipelines
      t.without_ms = std::min(t.without_ms, without.gpu_ms);
      if (with.gpu_ms >= t.with_ms) continue;
      t.with_ms = with.gpu_ms;
      t.passes_ms = 0;
      for (const PassStats& p : with.passes)
        if (p.name.starts_with("dof/")) t.passes_ms += p.gpu_ms;
    }
    return t;
  };
  renderer.set_graph(test::ibl_graph());
  renderer.render(world, frame);
  const std::vector<float> pinhole = renderer.executor().read_image("ibl.color");
  const bench::Regions r = bench::regions(renderer.executor().read_image("gbuf.gbuffer.depth"), camera, frame);
  const double max_blur = std::min(64.0, std::ceil(r.largest_coc));
  std::printf(
      "post.dof on %s, %ux%u, aperture %.3f m, focus %.2f m, vertical fov %.1f deg: circles up to %.2f px, "
      "max_blur %.0f; in focus %.1f%% of the frame, defocused %.1f%%\n",
      o.world.c_str(), o.width, o.height, o.aperture, camera.focus_distance,
      camera.vertical_fov * 180.0 / 3.14159265358979, r.largest_coc, max_blur, 100 * bench::share(r.focus),
      100 * bench::share(r.defocused));
  std::fflush(stdout);

  const std::vector<float> half = test::thin_lens_reference(renderer, world, frame, o.lens_samples / 2, "ibl.color");
  const std::vector<float> reference = test::thin_lens_reference(renderer, world, frame, o.lens_samples, "ibl.color");
  auto errors = [&](const std::vector<float>& image) {
    return std::vector<double>{bench::masked_error(image, reference, r.all),
                               bench::masked_error(image, reference, r.focus),
                               bench::masked_error(image, reference, r.defocused)};
  };
  const std::vector<double> pinhole_error = errors(pinhole), half_error = errors(half);
  std::printf("reference: %u lens samples; at %u against it: %.5f (all), %.5f (in focus), %.5f (defocused)\n",
              o.lens_samples, o.lens_samples / 2, half_error[0], half_error[1], half_error[2]);
  std::printf("pinhole (no depth of field): %.5f (all), %.5f (in focus), %.5f (defocused)\n", pinhole_error[0],
              pinhole_error[1], pinhole_error[2]);
  std::fflush(stdout);

  std::FILE* csv = std::fopen((o.results_dir + "/dof.csv").c_str(), "w");
  std::fprintf(csv,
               "samples,max_blur,dof_ms,passes_ms,frame_ms,frame_without_ms,error_all,error_focus,error_defocused,"
               "pinhole_error_all,reference_half_error_all\n");
  std::printf("\ntimes at %ux%u, errors at %ux%u\n%8s %9s %10s %10s %10s %12s %12s %12s\n", o.timing_width,
              o.timing_height, o.width, o.height, "samples", "dof ms", "passes ms", "frame ms", "without", "error all",
              "in focus", "defocused");
  for (const double s : o.samples) {
    const Graph graph = test::ibl_graph(R"({ "max_blur": )" + std::to_string(max_blur) + R"(, "samples": )" +
                                        std::to_string(int(s)) + " }");
    renderer.set_graph(graph);
    renderer.render(world, frame);
    const std::vector<double> e = errors(renderer.executor().read_image("dof.color"));
    timing.set_graph(graph);
    const Timing t = time_frames();
    const double dof = t.with_ms - t.without_ms;
    std::printf("%8d %9.1f %10.1f %10.1f %10.1f %12.5f %12.5f %12.5f\n", int(s), dof, t.passes_ms, t.with_ms,
                t.without_ms, e[0], e[1], e[2]);
    std::fflush(stdout);
    std::fprintf(csv, "%d,%.0f,%.3f,%.3f,%.3f,%.3f,%.6f,%.6f,%.6f,%.6f,%.6f\n", int(s), max_blur, dof, t.passes_ms,
                 t.with_ms, t.without_ms, e[0], e[1], e[2], pinhole_error[0], half_error[0]);
  }
  std::fclose(csv);
  std::printf("wrote dof.csv in %s\n", o.results_dir.c_str());
}
