// lumagraph-bench-volume: gi.irradiance_volume's passes on the device (lavapipe unless
// VK_ICD_FILENAMES says otherwise) at 1280x720.
// - Time, on the Cornell box (8 x 8 x 8 probes): every representation with and without
//   visibility at full resolution, and the default form at each --scales value below 1: the lookup
//   and upsample passes' GPU times from the executor's timestamps, median and least of --frames
//   frames after a first one (which bakes the probes and JIT-compiles the pipelines), the
//   process's CPU time per frame (less sensitive to other processes than the timestamps: lavapipe
//   runs the passes on its own threads), and the first frame's CPU time (the in-graph bake).
// - Error of each scale below 1 against full resolution, on the Cornell box and the two rooms:
//   relative RMS of the irradiance over the pixels either covers (sqrt(sum |dE|^2 / sum |E|^2)),
//   the share of pixels off by more than 10% of their value (edges), and the largest coverage
//   difference.
// The issue's target is 30 ms for the lookup. Prints tables and writes volume_lookup.csv and
// volume_upsample_error.csv into --results-dir.
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/load_world.h"
#include "tests/bench/bench_flags.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 1280, height = 720;
  int frames = 10;
  std::vector<double> scales = {0.5};
  bool all_forms = true;
};

struct Setting {
  std::string representation = "octahedral";
  bool visibility = true;
  double scale = 1.0;
};

Graph lookup_graph(const Setting& s) {
  Diagnostics d("volume-bench.json");
  std::ostringstream params;
  params << R"({ "representation": ")" << s.representation << R"(", "visibility": )"
         << (s.visibility ? "true" : "false") << R"(, "resolution_scale": )" << s.scale << " }";
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "volume", "type": "gi.irradiance_volume", "params": )" +
                                                    params.str() + R"( } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "volume.gbuffer" } ],
    "outputs": [ "volume.irradiance" ] })",
                                                d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

double process_cpu_ms() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

struct Times {
  double lookup_median = 0, lookup_least = 0, upsample_median = 0, total_median = 0, cpu_per_frame = 0, first_cpu = 0;
  std::vector<float> irradiance;  // the last frame's output
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Times run_setting(const World& world, const Setting& s, const Options& o) {
  Renderer renderer;
  renderer.set_graph(lookup_graph(s));
  Times t;
  t.first_cpu = renderer.render(world, {o.width, o.height}).cpu_ms;
  std::vector<double> lookup, upsample, total;
  const double cpu_start = process_cpu_ms();
  for (int f = 0; f < o.frames; ++f) {
    double l = 0, u = 0;
    for (const PassStats& pass : renderer.render(world, {o.width, o.height}).passes) {
      if (pass.name == "volume/lookup") l = pass.gpu_ms;
      if (pass.name == "volume/upsample") u = pass.gpu_ms;
    }
    lookup.push_back(l), upsample.push_back(u), total.push_back(l + u);
  }
  t.cpu_per_frame = (process_cpu_ms() - cpu_start) / o.frames;
  t.lookup_median = median(lookup), t.upsample_median = median(upsample), t.total_median = median(total);
  t.lookup_least = *std::min_element(lookup.begin(), lookup.end());
  t.irradiance = renderer.executor().read_image("volume.irradiance");
  return t;
}

struct ScaleError {
  double relative_rms = 0, share_over_10_percent = 0, coverage_difference = 0;
};

ScaleError compare(const std::vector<float>& full, const std::vector<float>& scaled) {
  ScaleError e;
  double difference = 0, magnitude = 0;
  size_t pixels = 0, off = 0;
  for (size_t p = 0; p + 3 < full.size(); p += 4) {
    e.coverage_difference = std::max(e.coverage_difference, double(std::abs(full[p + 3] - scaled[p + 3])));
    if (full[p + 3] == 0.0f && scaled[p + 3] == 0.0f) continue;
    double d2 = 0, m2 = 0;
    for (int c = 0; c < 3; ++c) d2 += std::pow(scaled[p + c] - full[p + c], 2.0), m2 += std::pow(full[p + c], 2.0);
    difference += d2, magnitude += m2;
    ++pixels;
    off += d2 > 0.01 * m2;  // more than 10% of the value
  }
  e.relative_rms = magnitude > 0 ? std::sqrt(difference / magnitude) : 0.0;
  e.share_over_10_percent = pixels ? double(off) / double(pixels) : 0.0;
  return e;
}

int run(const Options& o) {
  std::filesystem::create_directories(o.results_dir);
  std::ofstream csv(std::filesystem::path(o.results_dir) / "volume_lookup.csv");
  csv << "representation,visibility,resolution_scale,width,height,lookup_ms_median,lookup_ms_min,upsample_ms_median,"
         "total_ms_median,process_cpu_ms_per_frame,first_frame_cpu_ms\n";
  std::printf("gi.irradiance_volume, Cornell box, %ux%u, median of %d frames (GPU timestamps)\n", o.width, o.height,
              o.frames);
  std::printf("%-14s %-10s %6s %10s %10s %10s %10s %12s %12s\n", "form", "visibility", "scale", "lookup", "min",
              "upsample", "total ms", "CPU ms/frame", "bake+1st ms");
  std::vector<Setting> settings;
  for (const char* representation : {"sh_l1", "sh_l2", "ambient_cube", "octahedral"})
    for (bool visibility : {false, true})
      if (o.all_forms || std::string(representation) == "octahedral") settings.push_back({representation, visibility});
  for (double scale : o.scales) settings.push_back({"octahedral", true, scale});
  const World cornell = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  for (const Setting& s : settings) {
    const Times t = run_setting(cornell, s, o);
    std::printf("%-14s %-10s %6.2f %10.2f %10.2f %10.2f %10.2f %12.1f %12.0f\n", s.representation.c_str(),
                s.visibility ? "on" : "off", s.scale, t.lookup_median, t.lookup_least, t.upsample_median,
                t.total_median, t.cpu_per_frame, t.first_cpu);
    csv << s.representation << ',' << (s.visibility ? 1 : 0) << ',' << s.scale << ',' << o.width << ',' << o.height
        << ',' << t.lookup_median << ',' << t.lookup_least << ',' << t.upsample_median << ',' << t.total_median << ','
        << t.cpu_per_frame << ',' << t.first_cpu << '\n';
  }

  std::ofstream error_csv(std::filesystem::path(o.results_dir) / "volume_upsample_error.csv");
  error_csv << "world,resolution_scale,width,height,relative_rms,share_over_10_percent,max_coverage_difference\n";
  std::printf("\nupsampled against full resolution (octahedral, visibility on)\n%-12s %6s %14s %16s %14s\n", "world",
              "scale", "relative RMS", "pixels off >10%", "coverage diff");
  Options error_options = o;
  error_options.frames = 1;
  for (const char* world_name : {"cornell-box", "two-rooms"}) {
    const World world = load_world(std::string(LUMAGRAPH_SOURCE_DIR "/examples/worlds/") + world_name + ".json");
    const std::vector<float> full = run_setting(world, {}, error_options).irradiance;
    for (double scale : o.scales) {
      const ScaleError e = compare(full, run_setting(world, {"octahedral", true, scale}, error_options).irradiance);
      std::printf("%-12s %6.2f %13.2f%% %15.2f%% %14.4f\n", world_name, scale, 100 * e.relative_rms,
                  100 * e.share_over_10_percent, e.coverage_difference);
      error_csv << world_name << ',' << scale << ',' << o.width << ',' << o.height << ',' << e.relative_rms << ','
                << e.share_over_10_percent << ',' << e.coverage_difference << '\n';
    }
  }
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-volume [--results-dir DIR] [--size WxH] [--frames N] [--scales A,B,...] "
      "[--default-form-only]\n");
  flags.text("--results-dir", o.results_dir);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames);
  flags.numbers("--scales", o.scales);
  flags.set_switch("--default-form-only", o.all_forms, false);
  if (const auto status = flags.parse(argc, argv)) return *status;
  return lg::bench::run(o);
}
