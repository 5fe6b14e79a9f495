// lumagraph-bench-area-specular: the specular of sphere, tube and rectangle lights by linearly
// transformed cosines and by representative points against the double-precision quadrature of
// the GGX lobe over the light (tests/lighting/area_specular_cases.h), on --cases fresh shading
// points per light shape and horizon (lights 1.5 to 50 bounding radii away, roughness 0.1 to 1,
// n.v 0.02 to 1; --seed draws another set), and lighting.deferred's area pass GPU time with each
// (examples/default.json on the embedded default world, --frame-size, median over --frames after
// the first).
// Writes area_specular_errors.csv, area_specular_points.csv and area_specular_time.csv into
// --results-dir; scripts/run-area-specular-benchmarks plots them.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "tests/bench/area_pass_timing.h"
#include "tests/bench/bench_flags.h"
#include "tests/lighting/area_specular_cases.h"

namespace lg::bench {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string results_dir = "bench-results";
  int cases = 200;  // per shape and horizon
  uint32_t seed = 1000;  // of the first shape and horizon's points; the others' follow
  uint32_t frame_width = 1280, frame_height = 720, frames = 6;
  bool timing = true;
};

struct Point {
  SpecularCase c;
  SpecularSample s;
};

void write_errors(std::ofstream& csv, const std::string& group, const std::vector<Point>& points) {
  std::vector<SpecularSample> samples;
  for (const Point& p : points) samples.push_back(p.s);
  const SpecularErrors ltc = ltc_errors(samples), rp = representative_point_errors(samples);
  std::printf("%-24s %6zu %5d %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f\n", group.c_str(), samples.size(), ltc.lit,
              ltc.relative_rms, ltc.pointwise_rms, ltc.max_pointwise, rp.relative_rms, rp.pointwise_rms,
              rp.max_pointwise);
  csv << group << ',' << samples.size() << ',' << ltc.lit << ',' << ltc.relative_rms << ',' << ltc.pointwise_rms << ','
      << ltc.max_pointwise << ',' << rp.relative_rms << ',' << rp.pointwise_rms << ',' << rp.max_pointwise << '\n';
}

template <typename Keep>
std::vector<Point> only(const std::vector<Point>& points, Keep keep) {
  std::vector<Point> out;
  std::copy_if(points.begin(), points.end(), std::back_inserter(out), keep);
  return out;
}

int run(const Options& o) {
  const fs::path dir = fs::absolute(o.results_dir);
  fs::create_directories(dir);
  std::vector<Point> points;
  uint64_t seed = o.seed;
  for (LightShape shape : {LightShape::kSphere, LightShape::kTube, LightShape::kRect}) {
    for (Horizon horizon : {Horizon::kAbove, Horizon::kCrossing}) {
      CaseGenerator g(seed++);
      for (int k = 0; k < o.cases; ++k) {
        const SpecularCase c = make_specular_case(g, shape, SpecularRange{horizon});
        points.push_back({c, evaluate_specular(c)});
      }
    }
  }
  std::ofstream all(dir / "area_specular_points.csv");
  all << "shape,horizon,distance,roughness,n_dot_v,reference,ltc,representative_point,albedo\n";
  for (const Point& p : points)
    all << shape_name(p.c.shape) << ',' << (p.c.horizon == Horizon::kAbove ? "above" : "across") << ',' << p.c.distance
        << ',' << p.c.roughness << ',' << glm::dot(p.c.n, p.c.v) << ',' << p.s.reference << ',' << p.s.ltc << ','
        << p.s.representative_point << ',' << p.s.albedo << '\n';

  std::ofstream csv(dir / "area_specular_errors.csv");
  csv << "group,points,lit,ltc_relative_rms,ltc_pointwise_rms,ltc_max_pointwise,rp_relative_rms,rp_pointwise_rms,"
         "rp_max_pointwise\n";
  std::printf(
      "values as fractions of the lobe's albedo; rel RMS: RMS error / mean reference over all points; "
      "pointwise: (method - reference) / reference over lit points (reference >= %.0e of the albedo)\n",
      kLitShare);
  std::printf("%-24s %6s %5s %9s %9s %9s %9s %9s %9s\n", "group", "points", "lit", "LTC rel", "LTC pt", "LTC max",
              "RP rel", "RP pt", "RP max");
  write_errors(csv, "all", points);
  for (LightShape shape : {LightShape::kSphere, LightShape::kTube, LightShape::kRect}) {
    const std::string name = shape_name(shape);
    write_errors(csv, name, only(points, [&](const Point& p) { return p.c.shape == shape; }));
    write_errors(csv, name + " above",
                 only(points, [&](const Point& p) { return p.c.shape == shape && p.c.horizon == Horizon::kAbove; }));
    write_errors(csv, name + " across",
                 only(points, [&](const Point& p) { return p.c.shape == shape && p.c.horizon == Horizon::kCrossing; }));
  }
  const double bands[][2] = {{0.1, 0.25}, {0.25, 0.5}, {0.5, 0.75}, {0.75, 1.0}};
  for (const auto& band : bands) {
    char name[64];
    std::snprintf(name, sizeof name, "roughness %.2f-%.2f", band[0], band[1]);
    write_errors(csv, name, only(points, [&](const Point& p) {
                   return p.c.roughness >= band[0] && p.c.roughness < band[1] + 1e-9;
                 }));
  }
  const double distances[][2] = {{1.5, 3.0}, {3.0, 10.0}, {10.0, 50.0}};
  for (const auto& range : distances) {
    char name[64];
    std::snprintf(name, sizeof name, "distance %.1f-%.0f", range[0], range[1]);
    write_errors(csv, name,
                 only(points, [&](const Point& p) { return p.c.distance >= range[0] && p.c.distance < range[1]; }));
  }
  write_errors(csv, "grazing n.v < 0.2", only(points, [&](const Point& p) { return glm::dot(p.c.n, p.c.v) < 0.2; }));

  if (o.timing) {
    std::ofstream time(dir / "area_specular_time.csv");
    time << "method,area_ms\n";
    for (const std::string method : {"ltc", "representative_point"}) {
      const double ms = area_pass_ms(method, o.frame_width, o.frame_height, o.frames);
      std::printf("area pass, %s, %ux%u: %.1f ms (median of %u frames)\n", method.c_str(), o.frame_width,
                  o.frame_height, ms, o.frames);
      time << method << ',' << ms << '\n';
    }
  }
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-area-specular [--results-dir DIR] [--cases N] [--seed N] [--frame-size WxH] "
      "[--frames N] [--no-timing]\n");
  flags.text("--results-dir", o.results_dir);
  flags.count("--cases", o.cases);
  flags.count("--seed", o.seed);
  flags.size("--frame-size", o.frame_width, o.frame_height);
  flags.count("--frames", o.frames);
  flags.set_switch("--no-timing", o.timing, false);
  if (const auto status = flags.parse(argc, argv)) return *status;
  return lg::bench::run(o);
}
