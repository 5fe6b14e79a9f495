// lumagraph-bench-probes: irradiance-volume probes against the path-traced reference. For the
// Cornell box (examples/worlds/cornell-box.json, under env.sky's default sky) and the two rooms
// (examples/worlds/two-rooms.json, sealed), at three probe spacings (the world's volume, twice as
// coarse, and twice as fine), every representation (SH L1, SH L2, ambient cube, octahedral) with
// and without the Chebyshev visibility test: the indirect diffuse light the volume gives each
// G-buffer pixel (diffuse colour / pi x the looked-up irradiance) against the reference's
// indirect_diffuse AOV (bounces = the bake's + 1, so both carry the same light): relative RMS and
// mean absolute error over the pixels the volume covers, with the reference's own noise beside
// them and the RMS beyond that noise; the bake's wall time on all cores and the CPU lookup's time. For the two rooms
// also the leak: the dark room's mean floor irradiance over the lit room's, cameras in each room (the reference's is 0:
// the room is sealed). Writes probe_points.csv into --results-dir; scripts/run-probe-benchmarks plots it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "nodes/gi/path_tracer/path_tracer.h"
#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/gi/probes/probe_bake.h"
#include "nodes/gi/probes/probe_lookup.h"
#include "nodes/raytrace/camera_pixels.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/bench/bench_flags.h"

namespace lg::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 160, height = 120;
  uint32_t spp = 256, rays = 256, bounces = 3;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Pixel {
  VisibleSurface surface;
  glm::dvec3 reference, error;  // the reference's indirect diffuse and its standard error
};

struct World {
  std::string name;
  PathEnvironment environment;
  bool leak = false;
};

double leak_ratio(const ProbeGrid& grid, const ProbeLookupSettings& settings) {
  auto floor_mean = [&](double x0, double x1) {
    double sum = 0.0;
    int n = 0;
    for (double x = x0; x <= x1; x += 0.1)
      for (double z = -1.9; z <= 1.9; z += 0.2) {
        const auto e = lookup_irradiance(grid, {x, 0.0, z}, {0, 1, 0}, {x < 0.0 ? -3.7 : 3.7, 1.6, 1.7}, settings);
        sum += e ? e->g : 0.0, ++n;
      }
    return sum / n;
  };
  return floor_mean(0.05, 3.9) / floor_mean(-3.9, -0.05);
}

int run(const Options& o) {
  std::filesystem::create_directories(o.results_dir);
  std::ofstream csv(o.results_dir + "/probe_points.csv");
  csv << "world,probes,spacing_m,representation,visibility,bake_s,lookup_ms,relative_rms,relative_mae,reference_noise,"
         "beyond_noise,leak\n";
  std::printf("%-12s %-10s %8s %-13s %-4s %8s %9s %8s %8s %9s %8s %8s\n", "world", "probes", "spacing", "form", "vis",
              "bake s", "lookup ms", "rel RMS", "rel MAE", "ref noise", "beyond", "leak");
  for (const World& w : {World{"cornell-box", PathEnvironment::sky(SkyParams{}), false},
                         World{"two-rooms", PathEnvironment::none(), true}}) {
    const std::string path = std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/worlds/" + w.name + ".json";
    const SceneView view = make_scene_view(load_world(path), float(o.width) / o.height);
    const PathScene scene(view, w.environment);

    PathTracerOptions ro;
    ro.width = o.width, ro.height = o.height, ro.samples_per_pixel = o.spp, ro.max_bounces = o.bounces + 1;
    auto start = std::chrono::steady_clock::now();
    const ReferenceImage reference = trace_reference(scene, ro);
    std::printf("%s: reference %ux%u, %u paths, %u bounces in %.1f s\n", w.name.c_str(), o.width, o.height, o.spp,
                ro.max_bounces, seconds_since(start));
    const PathTransport transport(scene, 1);
    const CameraPixels camera(view.camera, o.width, o.height);
    std::vector<Pixel> pixels;
    for (uint32_t y = 0; y < o.height; ++y)
      for (uint32_t x = 0; x < o.width; ++x)
        if (auto s = transport.visible_surface(camera.eye(), camera.ray_direction(x, y), true)) {
          const size_t i = size_t(y) * o.width + x;
          pixels.push_back({*s, glm::dvec3(reference.mean_of(ReferenceAov::indirect_diffuse)[i]),
                            glm::dvec3(reference.error_of(ReferenceAov::indirect_diffuse)[i])});
        }

    const IrradianceVolumeData base = view.irradiance_volumes.at(0);
    for (double scale : {0.5, 1.0, 2.0}) {
      IrradianceVolumeData volume = base;
      volume.probe_counts = glm::max(glm::ivec3(glm::round(glm::dvec3(base.probe_counts - 1) * scale)) + 1, 2);
      ProbeGrid grid(volume);
      start = std::chrono::steady_clock::now();
      bake_probes(scene, grid, {.rays = o.rays, .bounces = o.bounces, .seed = 1}, 0, grid.probe_count());
      const double bake_s = seconds_since(start);
      const glm::ivec3 c = grid.counts();
      const std::string counts = std::to_string(c.x) + "x" + std::to_string(c.y) + "x" + std::to_string(c.z);
      for (ProbeRepresentation r : {ProbeRepresentation::sh_l1, ProbeRepresentation::sh_l2,
                                    ProbeRepresentation::ambient_cube, ProbeRepresentation::octahedral})
        for (bool visibility : {false, true}) {
          const ProbeLookupSettings settings{.representation = r, .visibility = visibility};
          double squared = 0.0, absolute = 0.0, reference_sum = 0.0, noise = 0.0;
          size_t n = 0;
          start = std::chrono::steady_clock::now();
          for (const Pixel& p : pixels) {
            const auto e = lookup_irradiance(grid, p.surface.position, p.surface.normal, camera.eye(), settings);
            if (!e) continue;
            const glm::dvec3 predicted = p.surface.diffuse_color / kPi * *e;
            for (int ch = 0; ch < 3; ++ch) {
              const double d = predicted[ch] - p.reference[ch];
              squared += d * d, absolute += std::abs(d), reference_sum += p.reference[ch];
              noise += p.error[ch] * p.error[ch];
            }
            n += 3;
          }
          const double lookup_ms = 1e3 * seconds_since(start);
          const double mean = reference_sum / double(n);
          const double rms = std::sqrt(squared / double(n)) / mean, mae = absolute / double(n) / mean;
          const double ref_noise = std::sqrt(noise / double(n)) / mean;
          // The RMS with the reference's own noise taken out (independent errors add in squares).
          const double beyond = std::sqrt(std::max(0.0, rms * rms - ref_noise * ref_noise));
          const double leak = w.leak ? leak_ratio(grid, settings) : std::nan("");
          std::printf("%-12s %-10s %8.3f %-13s %-4s %8.2f %9.1f %8.4f %8.4f %9.4f %8.4f %8.4f\n", w.name.c_str(),
                      counts.c_str(), grid.min_spacing(), probe_representation_name(r), visibility ? "on" : "off",
                      bake_s, lookup_ms, rms, mae, ref_noise, beyond, leak);
          csv << w.name << ',' << counts << ',' << grid.min_spacing() << ',' << probe_representation_name(r) << ','
              << (visibility ? "on" : "off") << ',' << bake_s << ',' << lookup_ms << ',' << rms << ',' << mae << ','
              << ref_noise << ',' << beyond << ',' << (w.leak ? std::to_string(leak) : "") << '\n';
        }
    }
  }
  std::printf("wrote %s/probe_points.csv\n", o.results_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-probes [--results-dir DIR] [--size WxH] [--spp N] [--rays N] [--bounces B]\n");
  flags.text("--results-dir", o.results_dir);
  flags.size("--size", o.width, o.height);
  flags.count("--spp", o.spp);
  flags.count("--rays", o.rays);
  flags.count("--bounces", o.bounces);
  if (const auto status = flags.parse(argc, argv)) return *status;
  return lg::bench::run(o);
}
