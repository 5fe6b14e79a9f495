// lumagraph-bench-env: the quality knobs of env.specular_prefilter and env.sh_project swept on
// lavapipe, each point's run time (GPU time between timestamps before and after its commands,
// the median of --runs runs after one discarded run that JIT-compiles the pipeline) next to its error against the
// double-precision references, on a 128^2 random environment and the probes of
// ../shared/data/env when present.
//   Prefilter: the node's exact method (exact_prefilter.h: its chain and peak list built inside
//   the timed commands), and samples 16 to 4096 of filtered importance sampling (method
//   'sampled', its own mip chain built inside the timed commands) and of plain GGX importance
//   sampling (mip 0 only), RMS relative error at roughness 0.25, 0.5, 1 and 0.75 over
//   kErrorTexels fixed random output texels; then the time ratio at equal error.
//   SH: orders 1 to 4 of cosine-convolved SH (irradiance): the truncation error (SH irradiance
//   against brute-force irradiance) and the implementation's own (GPU coefficients against the
//   double-precision projection, both reconstructed), over kErrorDirections random directions.
//   Irradiance: env.irradiance's 32^2 cube from source mips 1 to 4 (faces 64 to 8), relative RMS
//   against the brute-force irradiance of the full 128^2 map at kErrorTexels random texels.
// Writes env_prefilter.csv, env_prefilter_equal_error.csv, env_sh.csv and env_irradiance.csv; the plot is made by
// scripts/run-env-benchmarks.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "nodes/env/common/sh_basis.h"
#include "nodes/env/irradiance/irradiance_kernel.h"
#include "nodes/env/irradiance/irradiance_reference.h"
#include "nodes/env/sh_project/sh_project_kernel.h"
#include "nodes/env/sh_project/sh_reference.h"
#include "nodes/env/specular_prefilter/exact_prefilter.h"
#include "nodes/env/specular_prefilter/prefilter_reference.h"
#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/submit.h"
#include "runtime/gpu/timestamps.h"
#include "runtime/gpu/transfer.h"
#include "tests/env/env_test_support.h"

namespace lg::bench {
namespace {

constexpr uint32_t kFace = 128;
constexpr uint32_t kPrefilterMips = 5;  // mips 1 to 4 hold roughness 0.25, 0.5, 0.75 and 1
// In the CSV's column order: 0.25, 0.5 and 1 as they have always been, 0.75 added last.
constexpr uint32_t kLevels[] = {1, 2, 4, 3};
constexpr int kLevelCount = int(std::size(kLevels));
constexpr uint32_t kSampleCounts[] = {16, 64, 256, 1024, 4096};
constexpr int kShOrders[] = {1, 2, 3, 4};
constexpr uint32_t kIrradianceFace = 32;  // env.irradiance's default face_size
constexpr uint32_t kIrradianceSourceMips[] = {1, 2, 3, 4};  // 3: the default
constexpr int kErrorTexels = 150;      // per roughness, as the accuracy test
constexpr int kErrorDirections = 200;  // for the SH irradiance

// No validation layer: the timings are of the driver, not of the layer's checks (the accuracy
// tests run the same passes with it on).
struct Gpu {
  Context context{ContextOptions{}};
  Submitter submitter{context};
  PipelineCache pipelines{context};
  Sampler trilinear{context, {.filter = Filter::linear}};
  Sampler nearest{context, {.filter = Filter::nearest}};
};

Gpu& gpu() {
  static Gpu g;
  return g;
}

struct Texel {
  int face;
  uint32_t i, j;
  glm::dvec3 reference;
};

// One environment, rounded to half as the GPU sees it, with its references computed on first
// use and shared by every point of the sweep.
struct Probe {
  std::string name;
  CubeImage env;
  std::vector<std::vector<Texel>> prefilter_texels;  // per entry of kLevels
  std::vector<glm::dvec3> directions, irradiance;    // brute-force irradiance E along directions
  std::vector<Texel> irradiance_texels;               // brute-force E / pi at texels of a 32^2 cube

  const std::vector<std::vector<Texel>>& prefilter_references() {
    if (prefilter_texels.empty())
      for (int k = 0; k < kLevelCount; ++k) {
        const uint32_t size = kFace >> kLevels[k];
        const double roughness = prefilter_roughness(kLevels[k], kPrefilterMips);
        const CubeImage shape(size);
        std::mt19937_64 rng(40 + k);
        std::vector<Texel> texels;
        for (int t = 0; t < kErrorTexels; ++t) {
          const int f = int(rng() % 6);
          const uint32_t i = uint32_t(rng() % size), j = uint32_t(rng() % size);
          texels.push_back({f, i, j, prefiltered_reference(env, shape.direction(f, i, j), roughness)});
        }
        prefilter_texels.push_back(std::move(texels));
      }
    return prefilter_texels;
  }

  void irradiance_references() {
    if (!directions.empty()) return;
    std::mt19937_64 rng(70);
    std::normal_distribution<double> normal;
    for (int k = 0; k < kErrorDirections; ++k) {
      directions.push_back(glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng))));
      irradiance.push_back(std::numbers::pi * irradiance_over_pi_reference(env, directions.back()));
    }
  }

  const std::vector<Texel>& irradiance_cube_references() {
    if (irradiance_texels.empty()) {
      const CubeImage shape(kIrradianceFace);
      std::mt19937_64 rng(90);
      for (int t = 0; t < kErrorTexels; ++t) {
        const int f = int(rng() % 6);
        const uint32_t i = uint32_t(rng() % kIrradianceFace), j = uint32_t(rng() % kIrradianceFace);
        irradiance_texels.push_back({f, i, j, irradiance_over_pi_reference(env, shape.direction(f, i, j))});
      }
    }
    return irradiance_texels;
  }
};

std::vector<std::unique_ptr<Probe>> load_probes() {
  std::vector<std::unique_ptr<Probe>> probes;
  probes.push_back(std::make_unique<Probe>(
      Probe{"random", test::round_to_half(test::random_environment(kFace, 500)), {}, {}, {}, {}}));
  for (const char* name : {"grace.hdr", "pisa.hdr"}) {
    std::optional<CubeImage> env = test::load_probe(name, kFace);
    if (env)
      probes.push_back(std::make_unique<Probe>(Probe{name, test::round_to_half(std::move(*env)), {}, {}, {}, {}}));
    else
      std::printf("skipping %s: ../shared/data/env/%s is missing\n", name, name);
  }
  return probes;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Runs `record` once untimed (pipeline JIT), then once per benchmark iteration, timing it on the
// GPU (timestamps before and after its commands); the times go to the benchmark and to
// `times_ms`.
void time_runs(benchmark::State& state, const std::function<void(VkCommandBuffer)>& record,
               std::vector<double>& times_ms) {
  gpu().submitter.run(record);
  TimestampQueries timestamps(gpu().context, 1);
  for (auto _ : state) {
    gpu().submitter.run([&](VkCommandBuffer cmd) {
      timestamps.reset(cmd);
      const uint32_t scope = timestamps.begin(cmd, "bench");
      record(cmd);
      timestamps.end(cmd, scope);
    });
    const double ms = timestamps.results().front().milliseconds;
    state.SetIterationTime(1e-3 * ms);
    times_ms.push_back(ms);
  }
}

struct PrefilterPoint {
  std::string env;
  PrefilterSampling sampling;
  uint32_t samples;  // 0: the exact method (sampling unused)
  std::vector<double> times_ms;
  double rms[kLevelCount] = {};  // per entry of kLevels
  bool exact() const { return samples == 0; }
};

const char* method_name(const PrefilterPoint& p) {
  return p.exact() ? "exact" : p.sampling == PrefilterSampling::filtered ? "filtered" : "plain";
}

struct ShPoint {
  std::string env;
  int order;
  std::vector<double> times_ms;
  double truncation_rms = 0;      // SH irradiance (double-precision projection) vs brute force
  double implementation_rms = 0;  // GPU SH irradiance vs double-precision SH irradiance, / E
  double coefficient_error = 0;   // max |gpu - reference| / coefficient norm, worst channel
};

struct IrradiancePoint {
  std::string env;
  uint32_t source_mip;
  std::vector<double> times_ms;
  double rms = 0;  // relative, against the brute force over the whole 128^2 map
};

void bench_prefilter(benchmark::State& state, Probe& probe, PrefilterPoint& point) {
  const std::vector<CubeImage> chain = mip_chain(probe.env);
  Image source = test::make_cube(gpu().context, "env", kFace, uint32_t(chain.size()));
  test::upload_cube(gpu().submitter, source, chain, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  Image out = test::make_cube(gpu().context, "specular", kFace, kPrefilterMips);
  // Filtered sampling builds its own mip chain in the timed commands, as the node's pass does.
  Image own_chain = test::make_cube(gpu().context, "chain", kFace, uint32_t(chain.size()));
  Buffer peaks = Buffer::dedicated(gpu().context, {.name = "peaks", .size = prefilter_peaks_bytes()});
  const bool own = point.exact() || point.sampling == PrefilterSampling::filtered;
  time_runs(
      state,
      [&](VkCommandBuffer cmd) {
        image_barrier(cmd, out, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
        if (own) image_barrier(cmd, own_chain, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
        if (point.exact())
          record_specular_prefilter_exact(gpu().context, gpu().pipelines, cmd, "bench/prefilter", source, own_chain,
                                          gpu().nearest.handle(), peaks, out);
        else
          record_specular_prefilter(gpu().context, gpu().pipelines, cmd, "bench/prefilter", point.samples, source,
                                    own ? &own_chain : nullptr, gpu().trilinear.handle(), out, point.sampling);
        memory_barrier(cmd);
      },
      point.times_ms);
  const auto& references = probe.prefilter_references();
  for (int k = 0; k < kLevelCount; ++k) {
    const CubeImage mip = test::read_cube(gpu().submitter, out, kLevels[k], VK_IMAGE_LAYOUT_GENERAL);
    double sum = 0;
    for (const Texel& t : references[k])
      for (int c = 0; c < 3; ++c) {
        const double e = (mip.at(t.face, t.i, t.j)[c] - t.reference[c]) / t.reference[c];
        sum += e * e;
      }
    point.rms[k] = std::sqrt(sum / (3.0 * kErrorTexels));
    state.counters["rms_r" + std::to_string(prefilter_roughness(kLevels[k], kPrefilterMips)).substr(0, 4)] =
        point.rms[k];
  }
}

void bench_sh(benchmark::State& state, Probe& probe, ShPoint& point) {
  const ShProjectSettings settings = sh_project_settings(point.order, ShWindow::none, 0, true);
  Image cube = test::make_cube(gpu().context, "env", kFace, 1);
  test::upload_cube(gpu().submitter, cube, {probe.env}, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  const int count = sh_count(point.order);
  Buffer coefficients = Buffer::dedicated(gpu().context, {.name = "sh", .size = uint64_t(count) * 16});
  Buffer partials = Buffer::dedicated(gpu().context, {.name = "partials", .size = sh_partials_bytes(cube)});
  time_runs(
      state,
      [&](VkCommandBuffer cmd) {
        record_sh_project(gpu().context, gpu().pipelines, cmd, "bench/sh", settings, cube, gpu().nearest.handle(),
                          partials, coefficients);
        memory_barrier(cmd);
      },
      point.times_ms);

  const std::vector<std::byte> bytes = read_buffer(gpu().submitter, coefficients);
  std::vector<float> values(size_t(count) * 4);
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
  std::vector<glm::dvec3> sh;
  for (int k = 0; k < count; ++k) sh.emplace_back(values[4 * k], values[4 * k + 1], values[4 * k + 2]);
  const std::vector<glm::dvec3> reference =
      project_sh_reference(probe.env, point.order, settings.band_factors).coefficients;

  probe.irradiance_references();
  double truncation = 0, implementation = 0;
  for (size_t d = 0; d < probe.directions.size(); ++d) {
    const glm::dvec3 exact = probe.irradiance[d];
    const glm::dvec3 from_reference = evaluate_sh(reference, probe.directions[d]);
    const glm::dvec3 from_gpu = evaluate_sh(sh, probe.directions[d]);
    for (int c = 0; c < 3; ++c) {
      truncation += std::pow((from_reference[c] - exact[c]) / exact[c], 2);
      implementation += std::pow((from_gpu[c] - from_reference[c]) / exact[c], 2);
    }
  }
  point.truncation_rms = std::sqrt(truncation / (3.0 * kErrorDirections));
  point.implementation_rms = std::sqrt(implementation / (3.0 * kErrorDirections));
  for (int c = 0; c < 3; ++c) {
    double norm = 0, worst = 0;
    for (int k = 0; k < count; ++k) {
      norm += reference[k][c] * reference[k][c];
      worst = std::max(worst, std::abs(sh[k][c] - reference[k][c]));
    }
    point.coefficient_error = std::max(point.coefficient_error, worst / std::sqrt(norm));
  }
  state.counters["truncation_rms"] = point.truncation_rms;
  state.counters["implementation_rms"] = point.implementation_rms;
}

void bench_irradiance(benchmark::State& state, Probe& probe, IrradiancePoint& point) {
  const std::vector<CubeImage> chain = mip_chain(probe.env);
  Image source = test::make_cube(gpu().context, "env", kFace, uint32_t(chain.size()));
  test::upload_cube(gpu().submitter, source, chain, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  Image out = test::make_cube(gpu().context, "irradiance", kIrradianceFace, 1);
  Image sources;
  fit_irradiance_sources(gpu().context, "sources", source, point.source_mip, sources);
  time_runs(
      state,
      [&](VkCommandBuffer cmd) {
        image_barrier(cmd, out, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
        record_irradiance(gpu().context, gpu().pipelines, cmd, "bench/irradiance", point.source_mip, source,
                          gpu().nearest.handle(), sources, out);
        memory_barrier(cmd);
      },
      point.times_ms);
  const CubeImage result = test::read_cube(gpu().submitter, out, 0, VK_IMAGE_LAYOUT_GENERAL);
  double sum = 0;
  for (const Texel& t : probe.irradiance_cube_references())
    for (int c = 0; c < 3; ++c) sum += std::pow((result.at(t.face, t.i, t.j)[c] - t.reference[c]) / t.reference[c], 2);
  point.rms = std::sqrt(sum / (3.0 * kErrorTexels));
  state.counters["rms"] = point.rms;
}

// ---------------------------------------------------------------------------------------------
// Equal error: the plain curve's time (and sample count) at each filtered point's error,
// interpolated linearly in log-log between the plain points where the plain curve last comes
// down through that error (on the probes it is not monotonic: at few samples it misses the sun
// and is low by luck). Beyond the plain curve's ends, its nearest point is extended at the Monte
// Carlo rate (error ~ 1 / sqrt(samples), time ~ samples), and the row says it is extrapolated.

struct EqualError {
  std::string env;
  double roughness;
  uint32_t filtered_samples;
  double error, filtered_ms, plain_ms = 0, plain_samples = 0;
  bool extrapolated = false;
};

std::vector<EqualError> equal_error(const std::vector<PrefilterPoint>& points) {
  std::vector<EqualError> rows;
  for (const PrefilterPoint& f : points) {
    if (f.exact() || f.sampling != PrefilterSampling::filtered) continue;
    std::vector<const PrefilterPoint*> plain;
    for (const PrefilterPoint& p : points)
      if (p.env == f.env && !p.exact() && p.sampling == PrefilterSampling::plain_mip0) plain.push_back(&p);
    if (plain.size() < 2) continue;
    for (int k = 0; k < kLevelCount; ++k) {
      EqualError row{f.env, prefilter_roughness(kLevels[k], kPrefilterMips), f.samples, f.rms[k], median(f.times_ms)};
      const auto at_monte_carlo_rate = [&](const PrefilterPoint& from) {
        const double scale = std::pow(from.rms[k] / row.error, 2.0);
        row.plain_ms = median(from.times_ms) * scale;
        row.plain_samples = from.samples * scale;
        row.extrapolated = true;
      };
      size_t p = plain.size() - 1;  // the last segment [p - 1, p] that brackets the error
      while (p > 0 && !(plain[p - 1]->rms[k] >= row.error && plain[p]->rms[k] <= row.error)) --p;
      if (p > 0) {
        const PrefilterPoint &a = *plain[p - 1], &b = *plain[p];
        const double s = a.rms[k] == b.rms[k] ? 0.0 : std::log(row.error / a.rms[k]) / std::log(b.rms[k] / a.rms[k]);
        const auto along = [&](double x, double y) { return std::exp(std::log(x) + s * (std::log(y) - std::log(x))); };
        row.plain_ms = along(median(a.times_ms), median(b.times_ms));
        row.plain_samples = along(a.samples, b.samples);
      } else if (row.error < plain.back()->rms[k]) {
        at_monte_carlo_rate(*plain.back());
      } else if (row.error > plain.front()->rms[k]) {
        at_monte_carlo_rate(*plain.front());
      } else {
        continue;  // only reached through non-monotonic points: no comparison
      }
      rows.push_back(row);
    }
  }
  return rows;
}

// ---------------------------------------------------------------------------------------------

void print_and_write(const std::string& dir, const std::vector<PrefilterPoint>& prefilter,
                     const std::vector<EqualError>& equal, const std::vector<ShPoint>& sh,
                     const std::vector<IrradiancePoint>& irradiance) {
  std::printf(
      "\nSpecular prefilter, 128^2 output with 5 mips (all mips timed), RMS relative error over %d random\n"
      "texels per roughness against the double-precision brute force (samples 0: the exact method):\n",
      kErrorTexels);
  std::printf("%-10s %-9s %7s %10s %8s %9s %9s %9s %9s\n", "env", "method", "samples", "median ms", "min ms", "r=0.25",
              "r=0.5", "r=1", "r=0.75");
  std::ofstream csv(dir + "/env_prefilter.csv");
  csv << "env,sampling,samples,median_ms,min_ms,runs,rms_r0.25,rms_r0.5,rms_r1,rms_r0.75\n";
  for (const PrefilterPoint& p : prefilter) {
    const double med = median(p.times_ms), min = *std::min_element(p.times_ms.begin(), p.times_ms.end());
    std::printf("%-10s %-9s %7u %10.2f %8.2f %8.3f%% %8.3f%% %8.3f%% %8.3f%%\n", p.env.c_str(), method_name(p),
                p.samples, med, min, 100 * p.rms[0], 100 * p.rms[1], 100 * p.rms[2], 100 * p.rms[3]);
    csv << p.env << ',' << method_name(p) << ',' << p.samples << ',' << med << ',' << min << ',' << p.times_ms.size()
        << ',' << p.rms[0] << ',' << p.rms[1] << ',' << p.rms[2] << ',' << p.rms[3] << '\n';
  }

  std::printf(
      "\nEqual error: plain importance sampling's time and samples at the filtered point's error\n"
      "(log-log interpolation; '~' extrapolated beyond the plain curve's points):\n");
  std::printf("%-10s %5s %7s %9s %11s %10s %13s %9s %9s\n", "env", "r", "samples", "error", "filtered ms", "plain ms",
              "plain samples", "time x", "samples x");
  std::ofstream eq(dir + "/env_prefilter_equal_error.csv");
  eq << "env,roughness,filtered_samples,error,filtered_ms,plain_ms,plain_samples,time_ratio,sample_ratio,"
        "extrapolated\n";
  for (const EqualError& e : equal) {
    const char* gt = e.extrapolated ? "~" : " ";
    std::printf("%-10s %5.2f %7u %8.3f%% %11.2f %s%9.2f %s%12.0f %s%8.1f %s%8.1f\n", e.env.c_str(), e.roughness,
                e.filtered_samples, 100 * e.error, e.filtered_ms, gt, e.plain_ms, gt, e.plain_samples, gt,
                e.plain_ms / e.filtered_ms, gt, e.plain_samples / e.filtered_samples);
    eq << e.env << ',' << e.roughness << ',' << e.filtered_samples << ',' << e.error << ',' << e.filtered_ms << ','
       << e.plain_ms << ',' << e.plain_samples << ',' << e.plain_ms / e.filtered_ms << ','
       << e.plain_samples / e.filtered_samples << ',' << (e.extrapolated ? 1 : 0) << '\n';
  }

  std::printf(
      "\nSH projection of a 128^2 cube, cosine-convolved (irradiance), over %d random directions:\n"
      "truncation = SH irradiance (double precision) vs brute-force irradiance, relative RMS;\n"
      "implementation = GPU SH irradiance vs double-precision SH irradiance, RMS relative to E;\n"
      "coefficients = max |GPU - reference| / coefficient norm.\n",
      kErrorDirections);
  std::printf("%-10s %5s %10s %8s %11s %15s %13s\n", "env", "order", "median ms", "min ms", "truncation",
              "implementation", "coefficients");
  std::ofstream shcsv(dir + "/env_sh.csv");
  shcsv << "env,order,median_ms,min_ms,runs,truncation_rms,implementation_rms,coefficient_error\n";
  for (const ShPoint& p : sh) {
    const double med = median(p.times_ms), min = *std::min_element(p.times_ms.begin(), p.times_ms.end());
    std::printf("%-10s %5d %10.3f %8.3f %10.3f%% %14.2e %13.2e\n", p.env.c_str(), p.order, med, min,
                100 * p.truncation_rms, p.implementation_rms, p.coefficient_error);
    shcsv << p.env << ',' << p.order << ',' << med << ',' << min << ',' << p.times_ms.size() << ',' << p.truncation_rms
          << ',' << p.implementation_rms << ',' << p.coefficient_error << '\n';
  }

  std::printf(
      "\nIrradiance (env.irradiance), a %u^2 cube by cosine convolution of one source mip of the 128^2 map,\n"
      "relative RMS over %d random texels against the brute force over the whole 128^2 map:\n",
      kIrradianceFace, kErrorTexels);
  std::printf("%-10s %10s %11s %10s %8s %10s\n", "env", "source mip", "source face", "median ms", "min ms", "error");
  std::ofstream ircsv(dir + "/env_irradiance.csv");
  ircsv << "env,source_mip,source_face,median_ms,min_ms,runs,relative_rms\n";
  for (const IrradiancePoint& p : irradiance) {
    const double med = median(p.times_ms), min = *std::min_element(p.times_ms.begin(), p.times_ms.end());
    std::printf("%-10s %10u %11u %10.3f %8.3f %9.3f%%\n", p.env.c_str(), p.source_mip, kFace >> p.source_mip, med, min,
                100 * p.rms);
    ircsv << p.env << ',' << p.source_mip << ',' << (kFace >> p.source_mip) << ',' << med << ',' << min << ','
          << p.times_ms.size() << ',' << p.rms << '\n';
  }
}

const char* const usage =
    "usage: lumagraph-bench-env [--results-dir DIR] [--runs N] [--benchmark_filter=REGEX ...]\n"
    "  --results-dir DIR  where the CSV files go (default bench-results)\n"
    "  --runs N           timed runs per point, after one discarded run (default 7); the median is reported\n"
    "Run from the repository root: the probes are read from ../shared/data/env.\n";

int run(int argc, char** argv) {
  std::string results_dir = "bench-results";
  int runs = 7;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") return std::fputs(usage, stdout), 0;
    if (a == "--results-dir" && i + 1 < argc)
      results_dir = argv[++i];
    else if (a == "--runs" && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    else
      argv[kept++] = argv[i];
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  std::filesystem::create_directories(results_dir);

  std::vector<std::unique_ptr<Probe>> probes = load_probes();
  // Points are filled in as their benchmarks run; reserved so the references stay put.
  std::vector<PrefilterPoint> prefilter;
  std::vector<ShPoint> sh;
  std::vector<IrradiancePoint> irradiance;
  prefilter.reserve(probes.size() * (1 + 2 * std::size(kSampleCounts)));
  sh.reserve(probes.size() * std::size(kShOrders));
  irradiance.reserve(probes.size() * std::size(kIrradianceSourceMips));
  for (auto& probe : probes) {
    PrefilterPoint& exact = prefilter.emplace_back(PrefilterPoint{probe->name, PrefilterSampling::filtered, 0, {}});
    benchmark::RegisterBenchmark(("prefilter/" + probe->name + "/exact").c_str(),
                                 [&probe = *probe, &exact](benchmark::State& st) { bench_prefilter(st, probe, exact); })
        ->UseManualTime()
        ->Iterations(runs)
        ->Unit(benchmark::kMillisecond);
    for (PrefilterSampling s : {PrefilterSampling::filtered, PrefilterSampling::plain_mip0})
      for (uint32_t samples : kSampleCounts) {
        PrefilterPoint& point = prefilter.emplace_back(PrefilterPoint{probe->name, s, samples, {}});
        benchmark::RegisterBenchmark(
            ("prefilter/" + probe->name + "/" + (s == PrefilterSampling::filtered ? "filtered/" : "plain/") +
             std::to_string(samples))
                .c_str(),
            [&probe = *probe, &point](benchmark::State& st) { bench_prefilter(st, probe, point); })
            ->UseManualTime()
            ->Iterations(runs)
            ->Unit(benchmark::kMillisecond);
      }
    for (int order : kShOrders) {
      ShPoint& point = sh.emplace_back(ShPoint{probe->name, order, {}});
      benchmark::RegisterBenchmark(("sh/" + probe->name + "/" + std::to_string(order)).c_str(),
                                   [&probe = *probe, &point](benchmark::State& st) { bench_sh(st, probe, point); })
          ->UseManualTime()
          ->Iterations(runs)
          ->Unit(benchmark::kMillisecond);
    }
    for (uint32_t mip : kIrradianceSourceMips) {
      IrradiancePoint& point = irradiance.emplace_back(IrradiancePoint{probe->name, mip, {}});
      benchmark::RegisterBenchmark(
          ("irradiance/" + probe->name + "/" + std::to_string(mip)).c_str(),
          [&probe = *probe, &point](benchmark::State& st) { bench_irradiance(st, probe, point); })
          ->UseManualTime()
          ->Iterations(runs)
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  // Only what ran (a filter may have left points out).
  std::erase_if(prefilter, [](const PrefilterPoint& p) { return p.times_ms.empty(); });
  std::erase_if(sh, [](const ShPoint& p) { return p.times_ms.empty(); });
  std::erase_if(irradiance, [](const IrradiancePoint& p) { return p.times_ms.empty(); });
  print_and_write(results_dir, prefilter, equal_error(prefilter), sh, irradiance);
  std::printf("\nwrote %s/env_prefilter.csv, env_prefilter_equal_error.csv, env_sh.csv, env_irradiance.csv\n",
              results_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  return lg::bench::run(argc, argv);
}
