// lumagraph-bench-gi-methods: issue 18's one chart. Every diffuse global-illumination method run
// the way a user's graph runs it (examples/gi-volume.json, gi-lpv.json and gi-voxel.json, the
// node's quality params changed; "none": the same graphs' SH sky ambient alone), at three
// qualities each, against ONE path-traced reference per world of all the indirect diffuse light:
// the reference's indirect_diffuse AOV (every bounce of the world's lights and of the graphs' sky,
// --bounces surface interactions with Russian roulette after 3), on the Cornell box, the two rooms
// with a skylight (examples/worlds/two-rooms-sun.json) and the gallery. The references are cached
// under the build folder (reference_cache.h). Per method and quality:
// - its error: the irradiance lighting.ibl gives every pixel the reference sees, the graph's SH
//   ambient at the normal (times lighting.ibl's intensity, 0 in a world without an environment)
//   mixed toward the node's irradiance by its coverage, as ibl.comp does, before occlusion (the
//   graphs' GTAO multiplies every method alike and is left out), against the reference's
//   irradiance: the RMS over the reference's mean (tests/gi/prt_comparison.h, the measure of
//   lumagraph-bench-lpv and -probes), the reference's own noise in it and the RMS beyond it;
// - its cost: the node's passes' GPU time per frame at --frame-size inside the whole graph
//   (lavapipe; median and least of --frames frames after the first), the whole frame's CPU time,
//   the load average while it ran, and the first frame's wall time at --size (the probes' bake);
// - in the two rooms the leak: the east room's floor irradiance over the west room's
//   (two_rooms_leak.h; the reference's is 0);
// - for the dynamic methods (gi.lpv, gi.voxel, and gi.irradiance_volume in mode dynamic, at the
//   example graph's quality) the frames until the node's irradiance settles after the world's
//   directional lights turn --turn degrees about +y: the first frame after which its RMS distance
//   from what a fresh renderer gives in the turned world (gi.irradiance_volume: its static bake) stays
//   within a tenth of the distance the turn made.
// PRT is not among the methods: gi.prt carries the environment's light alone (none of the world's
// lights) and needs a bake per world; lumagraph-bench-prt measures it on environment-only worlds.
// Writes gi_methods.csv into --results-dir; scripts/run-gi-methods-benchmarks plots it.
#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "graph/json_writer.h"
#include "nodes/common/node_params.h"
#include "nodes/env/common/sh_basis.h"
#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "nodes/raytrace/camera_pixels.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/reference_cache.h"
#include "tests/bench/renderer_pass_timing.h"
#include "tests/bench/two_rooms_leak.h"
#include "tests/gi/prt_comparison.h"

namespace lg::bench {
namespace {

namespace fs = std::filesystem;
const std::string kSource = LUMAGRAPH_SOURCE_DIR;
// How far the directional lights turn before the settling is measured: far enough to move the
// sun's patch by many pixels, a move a game's time of day makes over seconds.
constexpr double kTurnDegrees = 10;

struct Options {
  std::string results_dir = "bench-results";
  std::string cache_dir = std::string(LUMAGRAPH_BINARY_DIR) + "/gi-reference-cache";
  uint32_t width = 160, height = 90;                // against the reference
  uint32_t frame_width = 1280, frame_height = 720;  // timed
  uint32_t spp = 512, bounces = 16, frames = 4;
  uint32_t settle_frames = 4, probe_settle_frames = 48;  // rendered after the turn
  double orbit = 2;  // degrees the camera turns each timed frame, and back: nothing kept for a still camera
  std::string worlds = "cornell-box,two-rooms-sun,gallery";
  std::string methods = "none,volume,lpv,voxel";  // which rows to run (the references are traced either way)
};

// One method at one quality: the example graph it runs in, its node's id there (its passes'
// prefix), the params set on the node, and for the probes the density of the world's volumes.
struct Method {
  std::string name;   // "none", "volume", "lpv", "voxel"
  std::string label;  // the quality, e.g. "16/8"
  std::string graph_file;
  std::vector<std::pair<std::string, double>> params;
  double probe_density = 1;  // probes along each axis (less one) times this
  bool example_quality = false;  // the example graph's own setting: the one measured for settling
};

std::vector<Method> methods() {
  std::vector<Method> out = {{"none", "-", "gi-lpv.json", {}, 1, false}};
  for (auto [density, rays] : {std::pair(0.5, 64), std::pair(1.0, 256), std::pair(2.0, 256)})
    out.push_back({"volume", "x" + std::string(density == 0.5 ? "1/2" : density == 1 ? "1" : "2") + " " +
                                 std::to_string(rays) + " rays",
                   "gi-volume.json", {{"rays", rays}}, density, density == 1});
  for (auto [grid, iterations] : {std::pair(8, 4), std::pair(16, 8), std::pair(32, 16)})
    out.push_back({"lpv", std::to_string(grid) + "/" + std::to_string(iterations), "gi-lpv.json",
                   {{"grid", grid}, {"iterations", iterations}}, 1, grid == 16});
  for (int resolution : {32, 64, 128})
    out.push_back({"voxel", std::to_string(resolution), "gi-voxel.json", {{"resolution", resolution}}, 1,
                   resolution == 64});
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double load_average() {
  double one = NAN;
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &one) != 1) one = NAN;
    std::fclose(f);
  }
  return one;
}

// The example graph with the method's params on its node, which (with the SH) becomes a graph
// output so that it can be read back; `extra` params too (the probes' mode).
Graph method_graph(const Method& m, const std::vector<std::pair<std::string, JsonValue>>& extra = {}) {
  Diagnostics d(m.graph_file);
  std::optional<Graph> graph = load_graph_file(kSource + "/examples/" + m.graph_file, d);
  if (!graph) throw std::runtime_error(d.to_string());
  for (GraphNode& node : graph->nodes)
    if (node.id == m.name) {
      for (const auto& [name, value] : m.params) node.params.set(name, JsonValue(value));
      for (const auto& [name, value] : extra) node.params.set(name, value);
    }
  if (m.name != "none") graph->outputs.push_back({{m.name, "irradiance"}, {}});
  graph->outputs.push_back({{"sh", "sh"}, {}});
  return std::move(*graph);
}

// What of the graphs the reference depends on besides the world: the environment node
// plan_environment picks, with its params (an edit to a GI node elsewhere in the graph keeps the
// cached reference).
std::string environment_key(const Plan& plan) {
  for (const PlanNode& node : plan.nodes)
    if (node.state == NodeState::Kind::active && (node.type == "env.load" || node.type == "env.sky"))
      return " " + node.type + "=" + write_json_compact(node.params);
  return " no-environment";
}

World with_probe_density(World world, double density) {
  world.each<IrradianceVolume>([&](Entity, IrradianceVolume& v) {
    v.probe_counts = glm::max(glm::ivec3(glm::round(glm::dvec3(v.probe_counts - 1) * density)) + 1, 2);
  });
  return world;
}

// The surfaces the camera sees at the reference's pixels: their normals (none: sky).
std::vector<std::optional<glm::dvec3>> visible_normals(const World& world, uint32_t width, uint32_t height) {
  const SceneView view = make_scene_view(world, float(width) / height);
  const PathScene scene(view, PathEnvironment::none());
  const PathTransport transport(scene, 1);
  const CameraPixels camera(view.camera, width, height);
  std::vector<std::optional<glm::dvec3>> out;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const auto s = transport.visible_surface(camera.eye(), camera.ray_direction(x, y), true);
      out.push_back(s ? std::optional(s->normal) : std::nullopt);
    }
  return out;
}

// What lighting.ibl uses as the diffuse irradiance after `renderer`'s last frame (ibl.comp): the
// SH ambient at the normal times its intensity, mixed toward node `node`'s irradiance by its
// coverage ("none": the ambient alone). RGBA, a = 1 where a surface is seen, else 0.
std::vector<float> ibl_irradiance(Renderer& renderer, const std::string& node,
                                  const std::vector<std::optional<glm::dvec3>>& normals) {
  const std::vector<std::byte> bytes = renderer.executor().read_buffer("sh.sh");
  std::vector<float> sh(bytes.size() / sizeof(float));
  std::memcpy(sh.data(), bytes.data(), sh.size() * sizeof(float));
  const int order = int(std::lround(std::sqrt(double(sh.size() / 4)))) - 1;
  double intensity = 0;  // lighting.ibl counts the environment as 0 in a world without one
  if (renderer.scene_view().has_environment)
    for (const PlanNode& n : renderer.plan().nodes)
      if (n.type == "lighting.ibl") intensity = param_number(n, "intensity");
  const std::vector<float> volume =
      node == "none" ? std::vector<float>() : renderer.executor().read_image(node + ".irradiance");
  std::vector<float> out(4 * normals.size(), 0.0f);
  std::vector<double> basis(size_t(sh_count(order)));
  for (size_t i = 0; i < normals.size(); ++i) {
    if (!normals[i]) continue;
    sh_evaluate(order, *normals[i], basis);
    for (int c = 0; c < 3; ++c) {
      double e = 0;
      for (size_t k = 0; k < basis.size(); ++k) e += basis[k] * sh[4 * k + size_t(c)];
      const double coverage = volume.empty() ? 0.0 : std::clamp(double(volume[4 * i + 3]), 0.0, 1.0);
      const double from_volume = volume.empty() ? 0.0 : volume[4 * i + size_t(c)];
      out[4 * i + size_t(c)] = float(intensity * e * (1 - coverage) + from_volume * coverage);
    }
    out[4 * i + 3] = 1.0f;
  }
  return out;
}

// The RMS of the rgb differences over the mean of `to`'s, where both cover a pixel.
double relative_distance(const std::vector<float>& from, const std::vector<float>& to) {
  double square = 0, sum = 0;
  size_t n = 0;
  for (size_t i = 0; i + 3 < to.size(); i += 4) {
    if (!(from[i + 3] > 0.0f && to[i + 3] > 0.0f)) continue;
    for (size_t c = 0; c < 3; ++c) square += std::pow(double(from[i + c]) - to[i + c], 2), sum += to[i + c], ++n;
  }
  return n && sum > 0 ? std::sqrt(square / double(n)) / (sum / double(n)) : NAN;
}

struct Settling {
  int frames = -1;          // -1: not within the frames rendered
  double turn_change = NAN;  // the distance the turn made, relative
  double last = NAN;         // the distance after the last frame, relative
};

// Frames until node `m.name`'s irradiance stays within a tenth of the turn's change of what a
// fresh renderer gives in the turned world (header comment).
Settling settle(const World& world, const Method& m, const Options& o) {
  const bool probes = m.name == "volume";
  const Graph graph = method_graph(m, probes ? std::vector<std::pair<std::string, JsonValue>>{{"mode", "dynamic"}}
                                             : std::vector<std::pair<std::string, JsonValue>>{});
  const FrameSize size{o.width, o.height};
  const std::string image = m.name + ".irradiance";
  World scene = world;
  Renderer renderer;
  renderer.set_graph(graph);
  renderer.render(scene, size);
  renderer.render(scene, size);
  const std::vector<float> before = renderer.executor().read_image(image);
  turn_directional_lights(scene, kTurnDegrees);
  Renderer fresh;
  fresh.set_graph(method_graph(m));
  fresh.render(scene, size);
  const std::vector<float> target = fresh.executor().read_image(image);
  Settling out;
  out.turn_change = relative_distance(before, target);
  const uint32_t frames = probes ? o.probe_settle_frames : o.settle_frames;
  for (uint32_t f = 1; f <= frames; ++f) {
    renderer.render(scene, size);
    out.last = relative_distance(renderer.executor().read_image(image), target);
    const bool within = out.last <= 0.1 * out.turn_change;
    if (!within) out.frames = -1;
    else if (out.frames < 0) out.frames = int(f);
  }
  return out;
}

struct Row {
  std::string world;
  const Method* method;
  test::PrtComparison error;
  double frame_ms = NAN, min_ms = NAN, frame_cpu_ms = NAN, load = NAN, first_frame_s = NAN, leak = NAN;
  std::string probes;  // the volumes' probe counts
  Settling settling;
};

int run(const Options& o) {
  const fs::path dir = fs::absolute(o.results_dir);
  fs::create_directories(dir);
  std::ofstream csv(dir / "gi_methods.csv");
  csv << "world,method,quality,frame_ms,relative_rms,reference_noise,beyond_noise,leak,frame_ms_min,mean_ratio,"
         "settle_frames,settle_last,frame_cpu_ms,load,first_frame_s,probes\n";
  std::printf("load average before: %.2f\n", load_average());
  std::printf("%-13s %-6s %-14s %9s %8s %8s %9s %8s %8s %6s %7s\n", "world", "method", "quality", "frame ms", "min ms",
              "rel RMS", "ref noise", "beyond", "leak", "scale", "settle");
  const std::vector<Method> all = methods();
  for (const std::string& name : split_commas(o.worlds)) {
    const std::string world_file = kSource + "/examples/worlds/" + name + ".json";
    const World world = load_world(world_file);
    const FrameSize size{o.width, o.height};
    const auto normals = visible_normals(world, o.width, o.height);
    // The graphs' environment (all three light their scene with one sky) and back-face culling.
    Renderer base;
    base.set_graph(method_graph(all.front()));
    base.render(world, size);
    const SceneView view = make_scene_view(world, float(o.width) / o.height);
    const PathScene scene(view, plan_environment(base.plan(), view.has_environment, "lumagraph-bench-gi-methods"));
    PathTracerOptions ro;
    ro.width = o.width, ro.height = o.height, ro.samples_per_pixel = o.spp, ro.max_bounces = o.bounces;
    ro.cull_backfaces = plan_culls_backfaces(base.plan(), true);
    char options[128], tag[64];
    std::snprintf(options, sizeof options, "size=%ux%u spp=%u bounces=%u cull=%d", o.width, o.height, o.spp,
                  o.bounces, int(ro.cull_backfaces));
    std::snprintf(tag, sizeof tag, "%ux%u-%u-b%u", o.width, o.height, o.spp, o.bounces);
    const ReferenceImage reference =
        cached_reference({o.cache_dir, name, {world_file}, options + environment_key(base.plan()), tag},
                         [&] { return trace_reference(scene, ro); });
    const bool rooms = name == "two-rooms-sun";

    const std::vector<std::string> chosen = split_commas(o.methods);
    for (const Method& m : all) {
      if (std::find(chosen.begin(), chosen.end(), m.name) == chosen.end()) continue;
      Row row;
      row.world = name, row.method = &m;
      const World w = with_probe_density(world, m.probe_density);
      if (m.name == "volume") {
        w.each<IrradianceVolume>([&](Entity, const IrradianceVolume& v) {
          row.probes += (row.probes.empty() ? "" : " ") + std::to_string(v.probe_counts.x) + "x" +
                        std::to_string(v.probe_counts.y) + "x" + std::to_string(v.probe_counts.z);
        });
      }
      Renderer renderer;
      renderer.set_graph(method_graph(m));
      auto start = std::chrono::steady_clock::now();
      renderer.render(w, size);
      row.first_frame_s = seconds_since(start);
      row.error = test::compare_with_reference(scene, reference, ibl_irradiance(renderer, m.name, normals));
      if (rooms)
        row.leak = two_rooms_floors(w, o.width, o.height, [&](const World& room) {
                     Renderer r;
                     r.set_graph(method_graph(m));
                     r.render(room, size);
                     return ibl_irradiance(r, m.name, visible_normals(room, o.width, o.height));
                   }).leak();
      if (m.name != "none" && o.frames > 0) {
        const std::string prefix = m.name + "/";
        renderer.render(w, {o.frame_width, o.frame_height});  // recompiles for the size (the probes may bake again)
        row.load = load_average();
        const double cpu_start = process_cpu_ms();
        const std::vector<double> ms =
            sorted_pass_ms(renderer, w, o.frame_width, o.frame_height, o.frames,
                           [&](const std::string& pass) { return pass.starts_with(prefix); }, o.orbit);
        row.frame_cpu_ms = (process_cpu_ms() - cpu_start) / (o.frames + 1);
        row.frame_ms = ms[ms.size() / 2], row.min_ms = ms.front();
      } else if (m.name == "none") {
        row.frame_ms = row.min_ms = 0;  // no node: the SH ambient is lighting.ibl's in every graph
      }
      if (m.example_quality && m.name != "none" && view.directional_lights.size() > 0)
        row.settling = settle(w, m, o);

      const test::PrtComparison& c = row.error;
      const double beyond =
          std::sqrt(std::max(0.0, c.rms_over_mean * c.rms_over_mean - c.noise_over_mean * c.noise_over_mean));
      const std::string leak = std::isfinite(row.leak) ? std::to_string(row.leak) : "";
      const std::string settle_text = std::isfinite(row.settling.turn_change) ? std::to_string(row.settling.frames) : "";
      std::printf("%-13s %-6s %-14s %9.2f %8.2f %8.4f %9.4f %8.4f %8s %6.3f %7s\n", name.c_str(), m.name.c_str(),
                  m.label.c_str(), row.frame_ms, row.min_ms, c.rms_over_mean, c.noise_over_mean, beyond, leak.c_str(),
                  c.mean_ratio, settle_text.c_str());
      if (!settle_text.empty())
        std::printf("  settling after a %.0f degree turn: change %.4f, after the last frame %.4f\n", kTurnDegrees,
                    row.settling.turn_change, row.settling.last);
      if (std::isfinite(row.frame_cpu_ms))
        std::printf("  whole frame's CPU time %.0f ms, load %.2f, first frame at %ux%u %.1f s%s%s\n",
                    row.frame_cpu_ms, row.load, o.width, o.height, row.first_frame_s, row.probes.empty() ? "" : ", probes ",
                    row.probes.c_str());
      csv << name << ',' << m.name << ',' << m.label << ',' << row.frame_ms << ',' << c.rms_over_mean << ','
          << c.noise_over_mean << ',' << beyond << ',' << leak << ',' << row.min_ms << ',' << c.mean_ratio << ','
          << settle_text << ',';
      if (std::isfinite(row.settling.last)) csv << row.settling.last;
      csv << ',';
      if (std::isfinite(row.frame_cpu_ms)) csv << row.frame_cpu_ms << ',' << row.load;
      else csv << ',';
      csv << ',' << row.first_frame_s << ',' << row.probes << '\n';
      csv.flush();
    }
  }
  std::printf("load average after: %.2f\nwrote %s\n", load_average(), (dir / "gi_methods.csv").c_str());
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-gi-methods [--results-dir DIR] [--cache-dir DIR] [--size WxH] [--frame-size WxH]\n"
      "                                  [--spp N] [--bounces N] [--frames N] [--settle-frames N]\n"
      "                                  [--probe-settle-frames N] [--worlds cornell-box,two-rooms-sun,gallery]\n"
      "                                  [--methods none,volume,lpv,voxel] [--orbit DEGREES]\n"
      "  --frames 0: no timing; --orbit (default 2): the camera turns by that much and back in turn\n"
      "  each timed frame (0: it stands still, and gi.voxel reuses its cones)\n");
  flags.text("--results-dir", o.results_dir);
  flags.text("--cache-dir", o.cache_dir);
  flags.size("--size", o.width, o.height);
  flags.size("--frame-size", o.frame_width, o.frame_height);
  flags.count("--spp", o.spp);
  flags.count("--bounces", o.bounces, 2);
  flags.count("--frames", o.frames, 0);
  flags.count("--settle-frames", o.settle_frames);
  flags.count("--probe-settle-frames", o.probe_settle_frames);
  flags.text("--worlds", o.worlds);
  flags.text("--methods", o.methods);
  std::vector<double> orbit;
  flags.numbers("--orbit", orbit);
  if (const auto status = flags.parse(argc, argv)) return *status;
  if (!orbit.empty()) o.orbit = orbit.front();
  if (!lg::bench::example_worlds_exist("lumagraph-bench-gi-methods", lg::bench::kSource, o.worlds)) return 2;
  if (!lg::bench::names_known("lumagraph-bench-gi-methods", "--methods", o.methods, {"none", "volume", "lpv", "voxel"}))
    return 2;
  return lg::bench::run(o);
}
