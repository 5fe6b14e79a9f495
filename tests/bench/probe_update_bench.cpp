// lumagraph-bench-probe-update: dynamic probe updates (nodes/gi/probes/probe_update.h) after a
// light moves. For the Cornell box (under env.sky's default sky; its lamp moved from the ceiling's
// centre toward the back of the green wall) and the two rooms (sealed; the lamp moved from the west
// room into the dark east one), the probes start from a full bake of the old scene (256 rays, 3
// bounces, as gi.irradiance_volume's defaults) and are updated with several budgets, ray counts
// and hysteresis values. After each update: the relative RMS of the irradiance looked up at the
// surfaces the volume serves (probe_difference.h) against a full bake of the new scene with
// 1,024 rays and 16 bounces (the updates' feedback carries any number of bounces; the default
// 3 leaves much out in a sealed room: printed beside). Reported: the updates (frames) until the
// error is within 10% and 5% and stays there, the same in sweeps over all probes, the error at
// the end (also beyond the reference's own noise, and per octahedral texel) and the mean over the
// reference's, and the wall and CPU time of one update on all cores. Writes
// probe_update.csv (one row per configuration) and probe_update_curves.csv (error per update)
// into --results-dir; scripts/run-probe-update-benchmarks plots the curves.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "nodes/gi/probes/probe_bake.h"
#include "nodes/gi/probes/probe_difference.h"
#include "nodes/gi/probes/probe_update.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/bench/bench_flags.h"

namespace lg::bench {
namespace {

// Updates until the error is within `bound` and stays there (-1: not by the end).
struct Within {
  double bound;
  int64_t update = -1;
  void see(double error, uint64_t u) {
    if (error > bound)
      update = -1;
    else if (update < 0)
      update = int64_t(u);
  }
};

struct Options {
  std::string results_dir = "bench-results";
  uint32_t sweeps = 40;  // updates run per configuration, in sweeps over all probes
  uint32_t reference_rays = 1024, reference_bounces = 16;
};

struct Scenario {
  std::string world;
  glm::vec3 lamp_before, lamp_after;
  bool sky;
};

struct Config {
  uint32_t budget, rays;
  double hysteresis;
};

std::vector<ProbeGrid> bake(const PathScene& scene, const ProbeBakeSettings& settings) {
  std::vector<ProbeGrid> grids;
  for (const IrradianceVolumeData& v : scene.view().irradiance_volumes) {
    ProbeGrid& g = grids.emplace_back(v);
    bake_probes(scene, g, settings, 0, g.probe_count());
  }
  return grids;
}

int run(const Options& o) {
  std::filesystem::create_directories(o.results_dir);
  std::ofstream csv(o.results_dir + "/probe_update.csv"), curves(o.results_dir + "/probe_update_curves.csv");
  csv << "world,probes,budget,rays,hysteresis,updates_to_10pct,sweeps_to_10pct,updates_to_5pct,sweeps_to_5pct,final_"
         "rms,"
         "final_beyond_noise,final_texel_rms,final_mean_ratio,final_rms_vs_3_bounces,update_wall_ms,update_cpu_ms\n";
  curves << "world,budget,rays,hysteresis,update,sweeps,relative_rms\n";
  const std::vector<Scenario> scenarios{{"cornell-box", {0.0f, 1.99f, 0.0f}, {0.65f, 1.99f, -0.6f}, true},
                                        {"two-rooms", {-2.0f, 2.99f, 0.0f}, {2.0f, 2.99f, 0.0f}, false}};
  const std::vector<Config> configs{{32, 128, 0.5},  {64, 128, 0.5}, {128, 128, 0.5}, {512, 128, 0.5},
                                    {64, 128, 0.25}, {64, 128, 0.8}, {64, 64, 0.5},   {64, 256, 0.5}};
  std::printf("%-12s %6s %6s %5s %5s %7s %6s %7s %6s %7s %7s %7s %6s %8s %8s %7s\n", "world", "probes", "budget",
              "rays", "hyst", "upd<10%", "sweeps", "upd<5%", "sweeps", "final", "beyond", "texels", "mean", "vs 3 bnc",
              "wall ms", "cpu ms");
  for (const Scenario& s : scenarios) {
    SceneView view =
        make_scene_view(load_world(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/worlds/" + s.world + ".json"), 1.0f);
    auto environment = [&] { return s.sky ? PathEnvironment::sky(SkyParams{}) : PathEnvironment::none(); };
    view.rect_lights.at(0).center = s.lamp_before;
    const PathScene before(view, environment());
    view.rect_lights.at(0).center = s.lamp_after;
    const PathScene after(view, environment());
    const ProbeLookupSettings lookup;
    const ProbeBakeSettings node_bake{.rays = 256, .bounces = 3, .seed = 1};
    ProbeBakeSettings full{.rays = o.reference_rays, .bounces = o.reference_bounces, .seed = 1};
    const std::vector<ProbeGrid> old_probes = bake(before, node_bake), three = bake(after, node_bake);
    const std::vector<ProbeGrid> reference = bake(after, full);
    full.seed = 2;
    const std::vector<ProbeGrid> other = bake(after, full);
    const std::vector<ServedPoint> points = served_points(after, reference, 16);
    const double seeds = lookup_difference(other, reference, points, lookup).relative_rms;
    size_t total = 0;
    for (const ProbeGrid& g : reference) total += g.probe_count();
    std::printf(
        "%s: %zu probes, %zu surface points; against the new scene's full bake: the old bake %.1f%%, the new "
        "3-bounce bake %.1f%%, a full bake of another seed %.1f%% (per texel %.1f%%)\n",
        s.world.c_str(), total, points.size(),
        100.0 * lookup_difference(old_probes, reference, points, lookup).relative_rms,
        100.0 * lookup_difference(three, reference, points, lookup).relative_rms, 100.0 * seeds,
        100.0 * probe_relative_rms(other, reference));
    for (const Config& c : configs) {
      const ProbeUpdateSettings settings{.probes_per_update = c.budget, .rays = c.rays, .hysteresis = c.hysteresis};
      std::vector<ProbeGrid> probes = old_probes;
      const size_t budget = std::min<size_t>(c.budget, total);
      const uint64_t updates = (uint64_t(o.sweeps) * total + budget - 1) / budget;
      Within within[2] = {{0.10}, {0.05}};
      double wall = 0.0, cpu = 0.0, error = lookup_difference(probes, reference, points, lookup).relative_rms;
      curves << s.world << ',' << c.budget << ',' << c.rays << ',' << c.hysteresis << ",0,0," << error << '\n';
      for (uint64_t u = 0; u < updates; ++u) {
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpu_start = std::clock();
        update_probes(after, probes, settings, u);
        cpu += double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        error = lookup_difference(probes, reference, points, lookup).relative_rms;
        for (Within& w : within) w.see(error, u + 1);
        curves << s.world << ',' << c.budget << ',' << c.rays << ',' << c.hysteresis << ',' << u + 1 << ','
               << double(u + 1) * budget / double(total) << ',' << error << '\n';
      }
      auto sweeps = [&](const Within& w) { return w.update < 0 ? -1.0 : double(w.update) * budget / double(total); };
      // The error with the reference's own noise taken out: independent errors add in squares,
      // and the reference's is half the square of two seeds' difference.
      const double beyond = std::sqrt(std::max(0.0, error * error - seeds * seeds / 2.0));
      const double texels = probe_relative_rms(probes, reference);
      const double mean = lookup_difference(probes, reference, points, lookup).mean_ratio;
      const double vs_three = lookup_difference(probes, three, points, lookup).relative_rms;
      const double wall_ms = 1e3 * wall / double(updates), cpu_ms = 1e3 * cpu / double(updates);
      std::printf(
          "%-12s %6zu %6zu %5u %5.2f %7lld %6.2f %7lld %6.2f %6.1f%% %6.1f%% %6.1f%% %6.3f %7.1f%% %8.1f %7.1f\n",
          s.world.c_str(), total, budget, c.rays, c.hysteresis, static_cast<long long>(within[0].update),
          sweeps(within[0]), static_cast<long long>(within[1].update), sweeps(within[1]), 100.0 * error, 100.0 * beyond,
          100.0 * texels, mean, 100.0 * vs_three, wall_ms, cpu_ms);
      csv << s.world << ',' << total << ',' << budget << ',' << c.rays << ',' << c.hysteresis << ',' << within[0].update
          << ',' << sweeps(within[0]) << ',' << within[1].update << ',' << sweeps(within[1]) << ',' << error << ','
          << beyond << ',' << texels << ',' << mean << ',' << vs_three << ',' << wall_ms << ',' << cpu_ms << '\n';
    }
  }
  std::printf("wrote %s/probe_update.csv and probe_update_curves.csv\n", o.results_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-probe-update [--results-dir DIR] [--sweeps N] [--reference-rays N] "
      "[--reference-bounces B]\n");
  flags.text("--results-dir", o.results_dir);
  flags.count("--sweeps", o.sweeps);
  flags.count("--reference-rays", o.reference_rays);
  flags.count("--reference-bounces", o.reference_bounces);
  if (const auto status = flags.parse(argc, argv)) return *status;
  return lg::bench::run(o);
}
