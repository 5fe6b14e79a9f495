// lumagraph-bench-ao: GTAO and SSAO on lavapipe at 1280x720 on the Stanford-bunny world, each
// point's GPU time (the occlusion node's passes, from the executor's timestamps; median and
// fastest of the frames after the first) next to its error against the camera-view ray-traced
// reference (512 stratified cosine rays per pixel on the full scene, GTAO's radius as the
// maximum distance with its falloff): mean absolute error and 95th percentile, on the first
// frame and after temporal accumulation over --frames frames. Points: the four GTAO presets,
// a slices x steps sweep, GTAO high and 2x6 at resolution_scale 0.5 and 0.25 (named "@0.5"),
// and SSAO's sample count. The G-buffer's depth traced as a height
// field (every --hf-stride-th pixel each way) splits the error into the method's (GTAO against
// the height field) and screen space's (the height field against the scene).
// The references are cached under the build folder, keyed by scene, camera, size and settings.
// Writes ao_points.csv and ao_references.csv; scripts/run-ao-benchmarks plots them.
#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "graph/fnv1a.h"
#include "nodes/occlusion/reference/height_field_reference.h"
#include "nodes/occlusion/reference/scene_reference.h"
#include "nodes/raytrace/world_mesh.h"
#include "tests/bench/bench_flags.h"
#include "tests/occlusion/ao_render.h"

namespace lg::bench {
namespace {

constexpr double kRadius = 0.5;  // GTAO's and SSAO's default radius, the reference's max distance

struct Options {
  std::string results_dir = "bench-results";
  std::string cache_dir = std::string(LUMAGRAPH_BINARY_DIR) + "/ao-reference-cache";
  uint32_t width = 1280, height = 720;
  int frames = 10;
  int rays = 512;
  uint32_t hf_stride = 8;
  std::string only;  // measure only the points whose "method config" contains this
};

struct Point {
  std::string method, config;
  int slices = 0, steps = 0, samples = 0;
  double scale = 1;  // GTAO's resolution_scale
  double median_ms = 0, min_ms = 0, frame_ms = 0;
  AoError first, accumulated, vs_height_field;
};

Point point_of(std::string method, std::string config, int slices = 0, int steps = 0, int samples = 0,
               double scale = 1) {
  Point p;
  p.method = std::move(method);
  p.config = std::move(config);
  p.slices = slices, p.steps = steps, p.samples = samples, p.scale = scale;
  return p;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// FNV-1a over what decides a reference: the camera, the size, the settings and the world-space
// geometry (its own hash), so a changed scene or camera never reads a stale file.
class Key {
 public:
  template <class T>
  Key& add(const T& value) {
    hash_ = fnv1a(&value, sizeof(T), hash_);
    return *this;
  }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = fnv1a_basis;
};

std::string cache_path(const Options& o, const char* kind, const SceneView& view, const AoSettings& s,
                       uint32_t stride) {
  Key key;
  key.add(view.camera.view).add(view.camera.projection).add(o.width).add(o.height).add(s.rays).add(s.max_distance);
  key.add(s.falloff_from).add(s.seed).add(stride);
  key.add(world_mesh_hash(make_world_mesh(view)));
  char name[128];
  std::snprintf(name, sizeof name, "/%s-%s-%ux%u-%016" PRIx64 ".bin", view.name.c_str(), kind, o.width, o.height,
                key.value());
  return o.cache_dir + name;
}

template <class Compute>
AoImage cached(const std::string& path, uint32_t width, uint32_t height, const char* what, Compute compute) {
  AoImage image(width, height);
  if (load_ao_image(path, image)) {
    std::printf("%s: cached in %s\n", what, path.c_str());
    return image;
  }
  const auto start = std::chrono::steady_clock::now();
  image = compute();
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::printf("%s: computed in %.1f s, saved to %s\n", what, seconds.count(), path.c_str());
  save_ao_image(path, image);
  return image;
}

void measure(std::vector<Point>& points, const World& world, const Options& o, const AoImage& reference,
             const AoImage& height_field, Point point, const std::string& node) {
  if ((point.method + " " + point.config).find(o.only) == std::string::npos) return;
  const test::AoRender r =
      test::render_occlusion(world, o.width, o.height, node, {.frames = o.frames, .validation = false});
  // The first frame compiles the pipelines (lavapipe JIT-compiles at the first dispatch).
  const std::vector<double> ms(r.ao_gpu_ms.begin() + 1, r.ao_gpu_ms.end());
  const std::vector<double> frame_ms(r.frame_gpu_ms.begin() + 1, r.frame_gpu_ms.end());
  point.median_ms = median(ms);
  point.min_ms = ms.empty() ? 0.0 : *std::min_element(ms.begin(), ms.end());
  point.frame_ms = median(frame_ms);
  point.first = error_against(reference, r.first_ao);
  point.accumulated = error_against(reference, r.last_ao);
  point.vs_height_field = error_against(height_field, r.last_ao);
  std::printf("%-5s %-12s %8.2f %8.2f %9.2f   %7.4f %7.4f   %7.4f %7.4f   %7.4f\n", point.method.c_str(),
              point.config.c_str(), point.median_ms, point.min_ms, point.frame_ms, point.first.mean_absolute,
              point.first.p95, point.accumulated.mean_absolute, point.accumulated.p95,
              point.vs_height_field.mean_absolute);
  std::fflush(stdout);
  points.push_back(std::move(point));
}

std::string gtao_node(const std::string& quality, int slices, int steps, double scale = 1) {
  return R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": ")" + quality + R"(", "slices": )" +
         std::to_string(slices) + R"(, "steps": )" + std::to_string(steps) +
         R"(, "radius": 0.5, "resolution_scale": )" + std::to_string(scale) + " } }";
}

std::string ssao_node(int samples) {
  return R"({ "id": "ao", "type": "occlusion.ssao", "params": { "samples": )" + std::to_string(samples) +
         R"(, "radius": 0.5 } })";
}

// The lowest GTAO error at or below time t (GTAO's lower envelope, stepwise), or nothing when
// every GTAO point is slower than t.
std::optional<double> gtao_envelope(const std::vector<Point>& points, double t, bool accumulated) {
  std::optional<double> best;
  for (const Point& p : points)
    if (p.method == "gtao" && p.min_ms <= t) {
      const double e = accumulated ? p.accumulated.mean_absolute : p.first.mean_absolute;
      best = best ? std::min(*best, e) : e;
    }
  return best;
}

// Whether GTAO has lower error than SSAO at equal time: at each SSAO point's time, the best
// GTAO point no slower than it must have a lower mean absolute error. Times are each point's
// fastest frame: on a shared machine other work only ever adds time, so the minimum is the
// least disturbed measure of what a pass costs (the medians are in the table and the CSV).
void print_dominance(const std::vector<Point>& points, bool accumulated) {
  int compared = 0, won = 0, faster = 0;
  std::printf("\nGTAO (%s) against SSAO at equal time (fastest frames; the best GTAO point no slower):\n",
              accumulated ? "after accumulation" : "first frame");
  for (const Point& s : points) {
    if (s.method != "ssao") continue;
    const std::optional<double> g = gtao_envelope(points, s.min_ms, accumulated);
    if (!g) {
      ++faster;
      std::printf("  ssao %-12s %7.2f ms  MAE %.4f: faster than every GTAO point\n", s.config.c_str(), s.min_ms,
                  s.accumulated.mean_absolute);
      continue;
    }
    ++compared;
    won += *g < s.accumulated.mean_absolute;
    std::printf("  ssao %-12s %7.2f ms  MAE %.4f   GTAO %.4f  %s\n", s.config.c_str(), s.min_ms,
                s.accumulated.mean_absolute, *g, *g < s.accumulated.mean_absolute ? "GTAO lower" : "SSAO lower");
  }
  // Dominance needs a GTAO point at least as fast as every SSAO point, each with lower error.
  const char* verdict = compared + faster == 0            ? "nothing to compare"
                        : compared > 0 && won == compared ? (faster == 0 ? "yes" : "partly")
                                                          : "no";
  std::printf(
      "GTAO dominates SSAO (%s): %s: lower error at %d of %d SSAO points with a GTAO point as fast; %d SSAO "
      "point(s) faster than every GTAO point\n",
      accumulated ? "after accumulation" : "first frame", verdict, won, compared, faster);
}

// Issue 21: no quality preset may be dominated by another GTAO configuration at its resolution
// scale, one with a lower error (after accumulation; errors are deterministic) and a fastest
// frame more than 10% faster. The 10% is the timing noise: the sweep measures each preset's
// slices x steps again minutes later, and on a quiet machine the twins' fastest frames differ by
// a few percent (docs/bench/ao); on a busy one by far more, and the verdict means little.
void print_preset_target(const std::vector<Point>& points) {
  constexpr double kFaster = 0.9;
  int presets = 0, dominated = 0;
  std::printf("\nGTAO quality presets against the other GTAO points at their resolution scale (dominated: lower MAE "
              "and a fastest frame under 90%% of the preset's):\n");
  for (const Point& p : points) {
    if (p.method != "gtao" || p.slices != 0 || p.config.find('@') != std::string::npos) continue;
    ++presets;
    const Point* by = nullptr;
    for (const Point& q : points)
      if (q.method == "gtao" && q.scale == p.scale && q.accumulated.mean_absolute < p.accumulated.mean_absolute &&
          q.min_ms < kFaster * p.min_ms && (!by || q.accumulated.mean_absolute < by->accumulated.mean_absolute))
        by = &q;
    dominated += by != nullptr;
    if (by)
      std::printf("  %-8s %7.2f ms  MAE %.4f: dominated by %s (%.2f ms, MAE %.4f)\n", p.config.c_str(), p.min_ms,
                  p.accumulated.mean_absolute, by->config.c_str(), by->min_ms, by->accumulated.mean_absolute);
    else
      std::printf("  %-8s %7.2f ms  MAE %.4f: on the envelope\n", p.config.c_str(), p.min_ms,
                  p.accumulated.mean_absolute);
  }
  std::printf("target no GTAO quality preset dominated: %s (%d of %d dominated)\n",
              presets == 0 ? "NOT MEASURED" : dominated == 0 ? "MET" : "NOT MET", dominated, presets);
}

void write_csv(const Options& o, const std::vector<Point>& points, const AoError& screen_space,
               const AoImage& reference, const AoImage& height_field) {
  std::ofstream csv(o.results_dir + "/ao_points.csv");
  csv << "method,config,slices,steps,samples,median_ms,min_ms,frame_ms,frames,mae_first,p95_first,mae_accumulated,"
         "p95_accumulated,mae_vs_height_field,p95_vs_height_field,resolution_scale\n";
  for (const Point& p : points)
    csv << p.method << ',' << p.config << ',' << p.slices << ',' << p.steps << ',' << p.samples << ',' << p.median_ms
        << ',' << p.min_ms << ',' << p.frame_ms << ',' << o.frames << ',' << p.first.mean_absolute << ',' << p.first.p95
        << ',' << p.accumulated.mean_absolute << ',' << p.accumulated.p95 << ',' << p.vs_height_field.mean_absolute
        << ',' << p.vs_height_field.p95 << ',' << p.scale << '\n';
  std::ofstream refs(o.results_dir + "/ao_references.csv");
  refs << "width,height,rays,max_distance,reference_pixels,height_field_stride,height_field_pixels,"
          "height_field_vs_scene_mae,height_field_vs_scene_p95,height_field_vs_scene_bias\n";
  refs << o.width << ',' << o.height << ',' << o.rays << ',' << kRadius << ',' << reference.covered_count() << ','
       << o.hf_stride << ',' << height_field.covered_count() << ',' << screen_space.mean_absolute << ','
       << screen_space.p95 << ',' << screen_space.mean_signed << '\n';
}

const char* const usage =
    "usage: lumagraph-bench-ao [--results-dir DIR] [--cache-dir DIR] [--size WxH] [--frames N] [--rays N]\n"
    "                          [--hf-stride N] [--only TEXT]\n"
    "  --results-dir DIR  where the CSV files go (default bench-results)\n"
    "  --cache-dir DIR    where the references are kept (default BUILD/ao-reference-cache)\n"
    "  --size WxH         frame size (default 1280x720)\n"
    "  --frames N         frames per point (default 10): the first is not timed, the last is the\n"
    "                     accumulated result\n"
    "  --rays N           reference rays per pixel (default 512)\n"
    "  --hf-stride N      height-field reference on every N-th pixel each way (default 8)\n"
    "  --only TEXT        only the points whose name (\"gtao high\", \"gtao 3x4\", \"ssao 16 samples\")\n"
    "                     contains TEXT\n"
    "Run from the repository root (it reads examples/worlds and ../shared/data).\n";

int run(int argc, char** argv) {
  Options o;
  BenchFlags flags(usage);
  flags.text("--results-dir", o.results_dir);
  flags.text("--cache-dir", o.cache_dir);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames, 2);
  flags.count("--rays", o.rays);
  flags.text("--only", o.only);
  flags.count("--hf-stride", o.hf_stride);
  if (const auto status = flags.parse(argc, argv)) return *status;
  std::filesystem::create_directories(o.results_dir);
  const World world = test::load_example_world("stanford-bunny");

  // One frame for the view and the G-buffer the references are traced for.
  const test::AoRender base =
      test::render_occlusion(world, o.width, o.height, gtao_node("high", 0, 0), {.frames = 1, .validation = false});
  const AoSettings settings{.rays = o.rays, .max_distance = kRadius};
  const AoImage reference =
      cached(cache_path(o, "scene", base.view, settings, 1), o.width, o.height, "ray-traced reference", [&] {
        const RayScene scene(base.view);
        return trace_scene_reference(base.view, scene, {o.width, o.height}, settings);
      });
  const AoImage height_field = cached(
      cache_path(o, "height-field", base.view, settings, o.hf_stride), o.width, o.height, "height-field reference",
      [&] { return trace_height_field_reference(base.view.camera, base.gbuffer, settings, o.hf_stride); });
  const AoError screen_space = error_against(reference, height_field);
  std::printf(
      "\n%ux%u, %d rays per pixel, radius %.2f m; %zu pixels with a surface. Height field (every %u-th pixel, %zu "
      "pixels) against the scene: MAE %.4f, p95 %.4f, bias %+.4f\n\n",
      o.width, o.height, o.rays, kRadius, reference.covered_count(), o.hf_stride, height_field.covered_count(),
      screen_space.mean_absolute, screen_space.p95, screen_space.mean_signed);
  std::printf("%-5s %-12s %8s %8s %9s   %-15s   %-15s   %s\n", "", "", "median", "min", "frame", "first frame",
              "accumulated", "vs height");
  std::printf("%-5s %-12s %8s %8s %9s   %7s %7s   %7s %7s   %7s\n", "node", "config", "ms", "ms", "ms", "MAE", "p95",
              "MAE", "p95", "field MAE");

  std::vector<Point> points;
  for (const char* quality : {"low", "medium", "high", "ultra"})
    measure(points, world, o, reference, height_field, point_of("gtao", quality), gtao_node(quality, 0, 0));
  for (int slices : {1, 2, 3, 4, 6})
    for (int steps : {2, 3, 4, 6, 8}) {
      const std::string config = std::to_string(slices) + "x" + std::to_string(steps);
      measure(points, world, o, reference, height_field, point_of("gtao", config, slices, steps),
              gtao_node("high", slices, steps));
    }
  for (const double scale : {0.5, 0.25}) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, " @%g", scale);
    measure(points, world, o, reference, height_field, point_of("gtao", std::string("high") + suffix, 0, 0, 0, scale),
            gtao_node("high", 0, 0, scale));
    measure(points, world, o, reference, height_field, point_of("gtao", std::string("2x6") + suffix, 2, 6, 0, scale),
            gtao_node("high", 2, 6, scale));
  }
  for (int samples : {4, 8, 16, 32, 64, 128}) {
    measure(points, world, o, reference, height_field,
            point_of("ssao", std::to_string(samples) + " samples", 0, 0, samples), ssao_node(samples));
  }
  print_dominance(points, false);
  print_dominance(points, true);
  print_preset_target(points);
  write_csv(o, points, screen_space, reference, height_field);
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  try {
    return lg::bench::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph-bench-ao: %s\n", e.what());
    return 1;
  }
}
