// lumagraph-bench-prt: gi.prt against the path-traced reference on environment-only versions of
// examples/worlds (two-spheres, cornell-box, gallery: their lights left out of the reference, as
// PRT carries the environment's light only), under examples/environments/studio.hdr. Per world
// and SH order 2, 3, 4: the bake's wall time (interreflected transfer, all cores), the node's GPU
// time per frame at --frame-size (lavapipe; the environment turning every frame, so nothing is
// cached), and at --size the relative RMS of its irradiance against the reference's
// (tests/gi/prt_comparison.h), the reference's own noise and the RMS beyond it, beside the
// environment's SH truncation error at that order. Writes prt_points.csv into --results-dir;
// scripts/run-prt-benchmarks plots it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/env/common/equirect.h"
#include "nodes/env/sh_project/sh_truncation.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "nodes/gi/prt/prt_file.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/renderer_pass_timing.h"
#include "tests/gi/prt_comparison.h"

namespace lg::bench {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 160, height = 90;                // against the reference
  uint32_t frame_width = 1280, frame_height = 720;  // timed
  uint32_t spp = 256, rays = 256, bounces = 2, frames = 8;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Graph prt_graph(const fs::path& dir, const std::string& bake, int order, double spin) {
  Diagnostics d("prt-bench.json");
  std::optional<Graph> graph =
      parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "env", "type": "env.load", "params": { "path": "studio.hdr", "face_size": 64 } },
      { "id": "sh", "type": "env.sh_project", "params": { "order": 4 } },
      { "id": "prt", "type": "gi.prt", "params": { "bake": ")" +
                           bake + R"(", "order": )" + std::to_string(order) + R"(, "spin": )" + std::to_string(spin) +
                           R"( } } ],
    "links": [ { "from": "env.cube", "to": "sh.env" }, { "from": "gbuf.gbuffer", "to": "prt.gbuffer" },
               { "from": "sh.sh", "to": "prt.sh" } ],
    "outputs": [ "prt.irradiance" ] })",
                       d);
  if (!graph) throw std::runtime_error(d.to_string());
  graph->file = (dir / "prt-bench.json").string();
  return std::move(*graph);
}

// The node's passes' GPU time, median over frames after the first (pipelines JIT-compiled).
double frame_ms(const fs::path& dir, const std::string& bake, int order, const World& world, const Options& o) {
  RendererOptions options;
  Renderer renderer(options);
  renderer.set_graph(prt_graph(dir, bake, order, 1.0));
  const std::vector<double> times = sorted_pass_ms(renderer, world, o.frame_width, o.frame_height, o.frames,
                                                   [](const std::string& name) { return name.starts_with("prt/"); });
  return times[times.size() / 2];
}

int run(const Options& o) {
  const fs::path dir = fs::absolute(o.results_dir);
  fs::create_directories(dir);
  fs::copy_file(LUMAGRAPH_SOURCE_DIR "/examples/environments/studio.hdr", dir / "studio.hdr",
                fs::copy_options::overwrite_existing);
  ImageData image = load_image((dir / "studio.hdr").string());
  sanitize_equirect(image.rgba, 1.0);
  const CubeImage env = equirect_to_cube(Equirect{image.width, image.height, std::move(image.rgba)}, 64, 4);

  std::ofstream csv(dir / "prt_points.csv");
  csv << "world,order,vertices,bake_s,frame_ms,relative_rms,reference_noise,beyond_noise,truncation_rms\n";
  std::printf("%-12s %5s %8s %8s %9s %8s %9s %8s %10s\n", "world", "order", "vertices", "bake s", "frame ms", "rel RMS",
              "ref noise", "beyond", "truncation");
  for (const std::string name : {"two-spheres", "cornell-box", "gallery"}) {
    const World world = load_world(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/worlds/" + name + ".json");
    SceneView view = make_scene_view(world, float(o.width) / o.height);
    view.directional_lights.clear(), view.point_lights.clear(), view.spot_lights.clear();
    view.sphere_lights.clear(), view.tube_lights.clear(), view.rect_lights.clear();
    const PathScene geometry(view, PathEnvironment::none());
    const size_t vertices = geometry.surfaces().mesh().positions.size();
    double bake_s[5] = {};
    for (int order : {2, 3, 4}) {
      const PrtSettings settings{
          .kind = TransferKind::interreflected, .order = order, .rays = o.rays, .bounces = o.bounces, .seed = 1};
      PrtFile file;
      file.header = make_prt_header(geometry.surfaces().mesh(), name, settings, 0, 1);
      const auto start = std::chrono::steady_clock::now();
      file.data = bake_transfer(geometry, settings, file.header.range);
      bake_s[order] = seconds_since(start);
      write_prt_file((dir / (name + "-" + std::to_string(order) + ".lgprt")).string(), file);
    }
    std::optional<PathScene> scene;
    std::optional<ReferenceImage> reference;
    for (int order : {2, 3, 4}) {
      const std::string bake = name + "-" + std::to_string(order) + ".lgprt";
      Renderer renderer;
      renderer.set_graph(prt_graph(dir, bake, order, 0.0));
      renderer.render(world, {o.width, o.height});
      if (!reference) {
        // The raster graph's environment, as `lumagraph reference` reads it; the light of as many
        // bounces as the bake carries (the visible surface and the bake's bounces after it).
        scene.emplace(view, plan_environment(renderer.plan(), true, "lumagraph-bench-prt"));
        PathTracerOptions ro;
        ro.width = o.width, ro.height = o.height, ro.samples_per_pixel = o.spp, ro.max_bounces = o.bounces + 1;
        const auto start = std::chrono::steady_clock::now();
        reference = trace_reference(*scene, ro);
        std::printf("%s: reference %ux%u, %u paths, %u bounces in %.1f s\n", name.c_str(), o.width, o.height, o.spp,
                    ro.max_bounces, seconds_since(start));
      }
      const test::PrtComparison c =
          test::compare_with_reference(*scene, *reference, renderer.executor().read_image("prt.irradiance"));
      const double ms = frame_ms(dir, bake, order, world, o);
      const double truncation = sh_irradiance_truncation_rms(env, order);
      std::printf("%-12s %5d %8zu %8.2f %9.2f %8.4f %9.4f %8.4f %10.4f\n", name.c_str(), order, vertices, bake_s[order],
                  ms, c.relative_rms, c.reference_noise, c.beyond_noise, truncation);
      csv << name << ',' << order << ',' << vertices << ',' << bake_s[order] << ',' << ms << ',' << c.relative_rms
          << ',' << c.reference_noise << ',' << c.beyond_noise << ',' << truncation << '\n';
    }
  }
  std::printf("wrote %s\n", (dir / "prt_points.csv").c_str());
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-prt [--results-dir DIR] [--size WxH] [--frame-size WxH] [--spp N] [--rays N] "
      "[--bounces B] [--frames N]\n");
  flags.text("--results-dir", o.results_dir);
  flags.size("--size", o.width, o.height);
  flags.size("--frame-size", o.frame_width, o.frame_height);
  flags.count("--spp", o.spp);
  flags.count("--rays", o.rays);
  flags.count("--bounces", o.bounces);
  flags.count("--frames", o.frames);
  if (const auto status = flags.parse(argc, argv)) return *status;
  return lg::bench::run(o);
}
