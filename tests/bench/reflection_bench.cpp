// lumagraph-bench-reflections: issue 17's reflections, error against time, on lavapipe. On the
// reflection room and the gallery with its floor polished (tests/lighting/reflection_worlds.h),
// each configuration of examples/reflections.json (the environment only, probes without and with
// parallax correction, SSR alone, SSR with the probes' fallback without and with it; and on a world
// with planar reflectors (the gallery's floor), examples/planar-reflections.json's planar
// reflections over the environment, over the probes and under SSR; quality knobs swept: the
// probes' face_size, SSR's max_steps and resolution_scale, the planar views' resolution_scale) gives
// - its error: the specular term against the path tracer's specular AOV over the floor's and the
//   ball's metal pixels (specular_error.h), at --size after --frames frames (SSR accumulates):
//   the mean absolute error against the reference, and the RMS error with the reference's noise
//   taken out (debiased_specular_error: the reference is traced as two halves with independent
//   seeds, whose mean is the reference of the first error); both also over the floor's pixels
//   that reflect only what the probes capture (captured_reflection_mask.h);
// - its time: the GPU time of the reflection passes (probes/*, planar/*, ssr/*, voxel/*: all of
//   gi.voxel's, its diffuse cones too) at --time-size,
//   median and fastest of the frames after the first; the CPU time of a frame after the first (lavapipe's
//   work is CPU work) less the environment-only configuration's, which a loaded machine disturbs
//   far less than the timestamps; and the first frame's extra host time over the later ones'
//   median (the probes' capture and prefilter, whichever way the node captures).
// Configurations are graph links and params only. The references are cached under the build
// folder, keyed by world, size, paths and the files they come from. Writes reflection_points.csv
// and reflection_references.csv; scripts/run-reflection-benchmarks plots them.
#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "graph/scene_summary.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/reference_cache.h"
#include "tests/lighting/captured_reflection_mask.h"
#include "tests/lighting/reflection_render.h"
#include "tests/lighting/reflection_worlds.h"
#include "tests/lighting/specular_error.h"

namespace lg::bench {
namespace {

using test::ReflectionConfig;
using test::ReflectionSource;

struct Options {
  std::string results_dir = "bench-results";
  std::string cache_dir = std::string(LUMAGRAPH_BINARY_DIR) + "/reflection-reference-cache";
  uint32_t width = 320, height = 180;             // where the error is measured
  uint32_t time_width = 1280, time_height = 720;  // where the passes are timed
  int frames = 8, time_frames = 4;
  uint32_t paths = 1024;
  std::vector<double> faces{16, 32, 64, 128}, steps{8, 16, 32, 64, 128}, scales{1}, planar_scales{1, 0.5, 0.25};
  std::vector<double> voxel_scales{0.5, 0.25};
  std::string worlds = "room,gallery";
  std::string only;  // measure only the configurations whose label contains this
  std::string probe_params;
  std::string maps_dir;      // where each configuration's error picture goes; empty: none
  bool errors_only = false;  // no timing at --time-size
};

struct Point {
  std::string world;
  ReflectionConfig config;
  double median_ms = 0, min_ms = 0, frame_ms = 0, first_extra_ms = 0;
  double cpu_ms = 0;  // median CPU time of a frame after the first, less the environment-only one's
  test::SpecularError all, floor, ball;
  test::DebiasedError floor_rms, ball_rms;
  test::SpecularError floor_captured;  // over the floor's pixels that reflect only captured entities
  test::DebiasedError floor_captured_rms;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The reference of `w` with `paths` a pixel from `seed`, from the cache when a file there was
// traced for the same run: the world and graph files (the environment is the graph's), the world's
// edits (its name), size, paths and seed.
ReferenceImage cached_reference(const Options& o, const test::ReflectionWorld& w, const std::string& world_file,
                                const PathEnvironment& environment, uint32_t paths, uint64_t seed) {
  const std::string source = LUMAGRAPH_SOURCE_DIR;
  char options[128], tag[64];
  std::snprintf(options, sizeof options, "size=%ux%u spp=%u seed=%" PRIu64, o.width, o.height, paths, seed);
  std::snprintf(tag, sizeof tag, "%ux%u-%u-s%" PRIu64, o.width, o.height, paths, seed);
  return bench::cached_reference(
      {o.cache_dir, w.name, {source + "/examples/worlds/" + world_file, source + "/examples/reflections.json"}, options,
       tag},
      [&] { return test::trace_specular_reference(w.world, o.width, o.height, paths, environment, seed); });
}

void print_error(const char* what, const test::SpecularError& e) {
  std::printf("  %-6s %6zu pixels, reference noise %.4f of its mean\n", what, e.pixels, e.noise);
}

// The reference as two halves of --paths with independent seeds, and their mean.
struct References {
  ReferenceImage a, b, mean;
};

class Measurer {
 public:
  Measurer(const Options& o, const test::ReflectionWorld& w, const References& references,
           const std::vector<uint8_t>& captured)
      : o_(o), w_(w), references_(references), reference_(references.mean), captured_(captured) {}

  void measure(ReflectionConfig config) {
    config.probe_params = o_.probe_params;
    const std::string label = test::config_label(config);
    if (!label_selected(label)) return;
    const Graph graph = test::reflection_graph(config);
    const test::ReflectionFrame e = test::render_reflections(w_.world, o_.width, o_.height, graph, o_.frames, false);
    Point p;
    p.world = w_.name;
    p.config = config;
    if (!o_.errors_only) time(graph, p);
    p.all = error(e, {});
    p.floor = error(e, {w_.floor_roughness});
    p.ball = error(e, {w_.ball_roughness});
    p.floor_rms = debiased(e, {w_.floor_roughness});
    p.ball_rms = debiased(e, {w_.ball_roughness});
    p.floor_captured = error(e, {w_.floor_roughness, &captured_});
    p.floor_captured_rms = debiased(e, {w_.floor_roughness, &captured_});
    if (!o_.maps_dir.empty()) save_picture(e, label);
    std::printf("%-16s %-34s %8.2f %8.2f %8.1f %9.1f %9.0f   %7.4f %7.4f %7.4f   %7.4f %7.4f   %7.4f %7.4f\n",
                p.world.c_str(), label.c_str(), p.median_ms, p.min_ms, p.cpu_ms, p.frame_ms, p.first_extra_ms,
                p.all.relative, p.floor.relative, p.ball.relative, p.floor_rms.rms, p.ball_rms.rms,
                p.floor_captured.relative, p.floor_captured_rms.rms);
    std::fflush(stdout);
    points.push_back(std::move(p));
  }

  std::vector<Point> points;

 private:
  // Whether --only (texts separated by '|') selects the label: one of them is in it.
  bool label_selected(const std::string& label) const {
    std::stringstream texts(o_.only);
    for (std::string text; std::getline(texts, text, '|');)
      if (label.find(text) != std::string::npos) return true;
    return o_.only.empty();
  }

  // The reflection passes' and the frame's times at --time-size.
  void time(const Graph& graph, Point& p) {
    const test::ReflectionFrame t =
        test::render_reflections(w_.world, o_.time_width, o_.time_height, graph, o_.time_frames, false);
    const std::vector<double> ms(t.reflection_gpu_ms.begin() + 1, t.reflection_gpu_ms.end());
    p.median_ms = median(ms);
    p.min_ms = *std::min_element(ms.begin(), ms.end());
    p.frame_ms = median({t.frame_gpu_ms.begin() + 1, t.frame_gpu_ms.end()});
    p.first_extra_ms = t.frame_wall_ms[0] - median({t.frame_wall_ms.begin() + 1, t.frame_wall_ms.end()});
    const double cpu = median({t.frame_cpu_ms.begin() + 1, t.frame_cpu_ms.end()});
    if (p.config.source == ReflectionSource::environment) environment_cpu_ms_ = cpu;
    p.cpu_ms = cpu - environment_cpu_ms_;
  }

  // The metal pixels' error picture (specular_error_picture, full colour at the reference's mean)
  // as MAPS/WORLD-LABEL.png, the label's spaces and '=' made '_'; with SSR, its confidence in grey
  // as MAPS/WORLD-LABEL-confidence.png.
  void save_picture(const test::ReflectionFrame& f, const std::string& label) const {
    std::string name = o_.maps_dir + "/" + w_.name + "-" + label;
    std::replace_if(
        name.begin() + o_.maps_dir.size(), name.end(), [](char c) { return c == ' ' || c == '='; }, '_');
    std::filesystem::create_directories(o_.maps_dir);
    save_image(name + ".png", 3 * o_.width, o_.height,
               test::specular_error_picture(reference_, f.lit, f.direct, f.material, {}, 1.0));
    if (f.ssr.empty()) return;
    std::vector<float> confidence(f.ssr.size(), 1.0f);
    for (size_t i = 0; i < f.ssr.size(); i += 4) confidence[i] = confidence[i + 1] = confidence[i + 2] = f.ssr[i + 3];
    save_image(name + "-confidence.png", o_.width, o_.height, confidence);
  }

  test::SpecularError error(const test::ReflectionFrame& f, test::SurfaceMask mask) const {
    return test::specular_error(reference_, f.lit, f.direct, f.material, mask);
  }

  test::DebiasedError debiased(const test::ReflectionFrame& f, test::SurfaceMask mask) const {
    return test::debiased_specular_error(references_.a, references_.b, f.lit, f.direct, f.material, mask);
  }

  const Options& o_;
  const test::ReflectionWorld& w_;
  const References& references_;
  const ReferenceImage& reference_;
  const std::vector<uint8_t>& captured_;
  double environment_cpu_ms_ = 0;  // measured first
};

bool has_planar_reflector(const World& world) {
  bool found = false;
  world.each<MeshRenderer>([&](Entity, const MeshRenderer& r) { found = found || r.reflector_plane.has_value(); });
  return found;
}

bool has_light(const World& world) {
  return make_scene_view(world, 1.0f).summary().has(SceneFeature::lights);
}

void measure_world(const Options& o, const test::ReflectionWorld& w, const std::string& world_file,
                   std::vector<Point>& points, std::ofstream& references) {
  // One small frame for the plan's environment, which the reference is lit by.
  const test::ReflectionFrame base = test::render_reflections(
      w.world, o.width, o.height, test::reflection_graph({.source = ReflectionSource::environment}), 1, false);
  References refs;
  refs.a = cached_reference(o, w, world_file, base.environment, o.paths / 2, 1);
  refs.b = cached_reference(o, w, world_file, base.environment, o.paths - o.paths / 2, 2);
  refs.mean = test::average_references(refs.a, refs.b);
  const ReferenceImage& reference = refs.mean;
  const auto noise = [&](test::SurfaceMask mask) {
    return test::specular_error(reference, base.lit, base.direct, base.material, mask);
  };
  const std::vector<uint8_t> captured =
      test::captured_reflection_mask(w.world, o.width, o.height, w.floor_roughness * w.floor_roughness);
  const auto noise_rms = [&](test::SurfaceMask mask) {
    return test::debiased_specular_error(refs.a, refs.b, base.lit, base.direct, base.material, mask).noise_rms;
  };
  print_error("metal", noise({-1.0f}));
  print_error("floor", noise({w.floor_roughness}));
  print_error("ball", noise({w.ball_roughness}));
  references << w.name << ',' << o.width << ',' << o.height << ',' << o.paths << ',' << noise({-1.0f}).noise << ','
             << noise({w.floor_roughness}).noise << ',' << noise({w.ball_roughness}).noise << ','
             << noise({w.floor_roughness}).pixels << ',' << noise({w.ball_roughness}).pixels << ','
             << noise_rms({w.floor_roughness}) << ',' << noise_rms({w.ball_roughness}) << ','
             << noise({w.floor_roughness, &captured}).noise << ',' << noise_rms({w.floor_roughness, &captured}) << ','
             << noise({w.floor_roughness, &captured}).pixels << '\n';
  std::printf("  RMS noise of the reference: floor %.4f, ball %.4f of its mean\n", noise_rms({w.floor_roughness}),
              noise_rms({w.ball_roughness}));
  std::printf("  floor reflecting only captured entities: %zu pixels, noise %.4f (RMS %.4f) of its mean\n",
              noise({w.floor_roughness, &captured}).pixels, noise({w.floor_roughness, &captured}).noise,
              noise_rms({w.floor_roughness, &captured}));
  std::printf("\n%-16s %-34s %8s %8s %8s %9s %9s   %-23s   %-15s   %-15s\n", "", "", "median", "min", "CPU", "frame",
              "1st frame", "mean |error| / ref mean", "debiased RMS", "floor, captured");
  std::printf("%-16s %-34s %8s %8s %8s %9s %9s   %7s %7s %7s   %7s %7s   %7s %7s\n", "world", "configuration",
              "GPU ms", "GPU ms", "extra ms", "GPU ms", "extra ms", "metal", "floor", "ball", "floor", "ball", "|error|",
              "RMS");

  Measurer m(o, w, refs, captured);
  m.measure({.source = ReflectionSource::environment});
  for (const bool parallax : {false, true})
    for (const double face : o.faces)
      m.measure({.source = ReflectionSource::probes, .parallax = parallax, .face_size = int(face)});
  for (const double scale : o.scales)
    for (const double steps : o.steps)
      m.measure({.source = ReflectionSource::ssr, .max_steps = int(steps), .ssr_scale = scale});
  for (const double scale : o.scales)
    for (const bool parallax : {false, true})
      for (const double face : o.faces)
        m.measure({.source = ReflectionSource::ssr_with_probes,
                   .parallax = parallax,
                   .face_size = int(face),
                   .ssr_scale = scale});
  // Elsewhere the planar node is bypassed: these would repeat the configurations above.
  if (has_planar_reflector(w.world))
    for (const ReflectionSource source :
         {ReflectionSource::planar, ReflectionSource::planar_with_probes, ReflectionSource::planar_with_ssr})
      for (const double scale : o.planar_scales) m.measure({.source = source, .planar_scale = scale});
  // gi.voxel carries the lights' bounce and, with `sh` linked, the sky's; with neither it is bypassed.
  for (const double scale : o.voxel_scales)
    for (const bool sky : {true, false})
      if (sky || has_light(w.world))
        m.measure({.source = ReflectionSource::voxel, .voxel_scale = scale, .voxel_sky = sky});
  std::printf("\n");
  points.insert(points.end(), m.points.begin(), m.points.end());
}

void write_points(const Options& o, const std::vector<Point>& points) {
  std::ofstream csv(o.results_dir + "/reflection_points.csv");
  csv << "world,source,parallax,face_size,max_steps,ssr_scale,median_ms,min_ms,frame_ms,first_frame_extra_ms,"
         "error_metal,error_floor,error_ball,pixels_floor,pixels_ball,noise_metal,label,cpu_ms,planar_scale,"
         "rms_floor,rms_ball,plain_rms_floor,plain_rms_ball,error_floor_captured,rms_floor_captured,"
         "pixels_floor_captured,voxel_scale\n";
  for (const Point& p : points) {
    const ReflectionConfig& c = p.config;
    csv << p.world << ',' << test::reflection_source_name(c.source) << ',' << c.parallax << ',' << c.face_size << ','
        << c.max_steps << ',' << (c.ssr_scale > 0 ? c.ssr_scale : 1.0) << ',' << p.median_ms << ',' << p.min_ms << ','
        << p.frame_ms << ',' << p.first_extra_ms << ',' << p.all.relative << ',' << p.floor.relative << ','
        << p.ball.relative << ',' << p.floor.pixels << ',' << p.ball.pixels << ',' << p.all.noise << ','
        << test::config_label(c) << ',' << p.cpu_ms << ',' << (c.planar_scale > 0 ? c.planar_scale : 0.0) << ','
        << p.floor_rms.rms << ',' << p.ball_rms.rms << ',' << p.floor_rms.plain_rms << ',' << p.ball_rms.plain_rms
        << ',' << p.floor_captured.relative << ',' << p.floor_captured_rms.rms << ',' << p.floor_captured.pixels
        << ',' << (c.voxel_scale > 0 ? c.voxel_scale : 0.0) << '\n';
  }
}

const char* const usage =
    "usage: lumagraph-bench-reflections [--results-dir DIR] [--cache-dir DIR] [--size WxH] [--time-size WxH]\n"
    "                                   [--frames N] [--time-frames N] [--paths N] [--faces A,B] [--steps A,B]\n"
    "                                   [--scales A,B] [--planar-scales A,B] [--worlds room,gallery] [--only TEXT]\n"
    "                                   [--voxel-scales A,B] [--probe-params JSON] [--maps DIR] [--errors-only]\n"
    "  --results-dir DIR   where the CSV files go (default bench-results)\n"
    "  --cache-dir DIR     where the references are kept (default BUILD/reflection-reference-cache)\n"
    "  --size WxH          size the error is measured at (default 320x180)\n"
    "  --time-size WxH     size the passes are timed at (default 1280x720)\n"
    "  --frames N          frames rendered before the error is taken (default 8; SSR accumulates)\n"
    "  --time-frames N     frames timed, the first not counted (default 4)\n"
    "  --paths N           reference paths per pixel (default 1024), traced as two halves with\n"
    "                      independent seeds (for the debiased RMS error)\n"
    "  --faces LIST        gi.reflection_capture face sizes (default 16,32,64,128)\n"
    "  --steps LIST        lighting.ssr max_steps (default 8,16,32,64,128)\n"
    "  --scales LIST       lighting.ssr resolution_scale values (default 1)\n"
    "  --planar-scales LIST gi.planar_reflection resolution_scale values, on worlds with planar reflectors\n"
    "                      (default 1,0.5,0.25)\n"
    "  --voxel-scales LIST gi.voxel resolution_scale values (without its sky: on worlds with a light)\n"
    "                      (default 0.5,0.25)\n"
    "  --worlds LIST       room, gallery, cornell (the Cornell box, floor and tall block metal)\n"
    "                      (default room,gallery)\n"
    "  --only TEXT         only configurations whose label (\"ssr+probes face=64\") contains TEXT, or one\n"
    "                      of several separated by '|' (\"environment|voxel\")\n"
    "  --probe-params JSON more gi.reflection_capture params as JSON members, e.g. '\"samples\": 64'\n"
    "  --maps DIR          also write each configuration's error picture there: its specular term, the\n"
    "                      reference's and the signed difference (red too bright, blue too dark)\n"
    "  --errors-only       measure the errors alone, without timing at --time-size\n";

int run(int argc, char** argv) {
  Options o;
  BenchFlags flags(usage);
  flags.text("--results-dir", o.results_dir);
  flags.text("--cache-dir", o.cache_dir);
  flags.size("--size", o.width, o.height);
  flags.size("--time-size", o.time_width, o.time_height);
  flags.count("--frames", o.frames);
  flags.count("--time-frames", o.time_frames, 2);
  flags.count("--paths", o.paths, 2);  // two halves
  flags.numbers("--faces", o.faces);
  flags.numbers("--steps", o.steps);
  flags.numbers("--scales", o.scales);
  flags.numbers("--planar-scales", o.planar_scales);
  flags.numbers("--voxel-scales", o.voxel_scales);
  flags.text("--worlds", o.worlds);
  flags.text("--only", o.only);
  flags.text("--probe-params", o.probe_params);
  flags.text("--maps", o.maps_dir);
  flags.set_switch("--errors-only", o.errors_only, true);
  if (const auto status = flags.parse(argc, argv)) return *status;
  std::filesystem::create_directories(o.results_dir);
  std::ofstream references(o.results_dir + "/reflection_references.csv");
  references << "world,width,height,paths,noise_metal,noise_floor,noise_ball,pixels_floor,pixels_ball,"
                "noise_rms_floor,noise_rms_ball,noise_floor_captured,noise_rms_floor_captured,pixels_floor_captured\n";
  std::vector<Point> points;
  std::printf(
      "Specular term against the path tracer's specular AOV (%ux%u, %u paths a pixel, %d frames), reflection "
      "passes timed at %ux%u. Errors: mean |error| / mean reference over the metal pixels, the floor's, the "
      "ball's.\n",
      o.width, o.height, o.paths, o.frames, o.time_width, o.time_height);
  if (o.worlds.find("room") != std::string::npos)
    measure_world(o, test::reflection_room(), "reflection-room.json", points, references);
  if (o.worlds.find("gallery") != std::string::npos)
    measure_world(o, test::polished_gallery(), "gallery.json", points, references);
  if (o.worlds.find("cornell") != std::string::npos)
    measure_world(o, test::polished_cornell_box(), "cornell-box.json", points, references);
  write_points(o, points);
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  try {
    return lg::bench::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph-bench-reflections: %s\n", e.what());
    return 1;
  }
}
