// lumagraph-bench-compile: how long compile() takes and how much heap it needs on synthetic
// graphs (chains and random DAGs of 10 to 10,000 nodes), how much of load+compile is parsing,
// where the time goes phase by phase, and how much transient memory aliasing saves on the
// example graphs. Writes CSV files and checks the numbers against the targets of the issue.
//
//   lumagraph-bench-compile [--results-dir DIR] [--examples-dir DIR] [--phase-runs N]
//                           [--memory-table | --phase-table] [--benchmark_* flags]
//
// A benchmark, not a test: nothing here fails on a slow time, and ctest never runs it.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "graph/block_cache.h"
#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "graph/plan_format.h"
#include "tests/bench/heap_tracker.h"
#include "tests/bench/memory_table.h"
#include "tests/support/synthetic_graphs.h"

namespace lg::bench {
namespace {

constexpr int64_t sizes[] = {10, 100, 1000, 10000};
constexpr double mib = 1024.0 * 1024.0;

// ---------------------------------------------------------------------------------------------
// Inputs

enum class Kind { chain, random_dag };
const char* kind_name(Kind k) { return k == Kind::chain ? "chain" : "random_dag"; }

// Random DAGs of each size come in 16 seeds, measured in turn: a processor that compiles one
// small graph over and over learns it (its branches, likely: the data fits in cache either
// way). One 100-node DAG compiled 0.063 ms a time, 16 in turn 0.083 ms; from 1,000 nodes up
// the two are within 4%. There is one chain a length.
constexpr int dag_seeds = 16;
int variants(Kind kind) {
  return kind == Kind::chain ? 1 : dag_seeds;
}

test::RandomDagOptions dag_options(size_t nodes, int variant = 0) {
  return {.nodes = nodes,
          .dead_fraction = 0.3,
          .history_fraction = 0.05,
          .window = 12,
          .seed = 1 + static_cast<uint64_t>(variant)};
}

const Graph& graph_for(Kind kind, size_t nodes, int variant = 0) {
  static std::map<std::tuple<Kind, size_t, int>, Graph> cache;
  auto [it, inserted] = cache.try_emplace({kind, nodes, variant});
  if (inserted)
    it->second = kind == Kind::chain ? test::make_chain(nodes) : test::make_random_dag(dag_options(nodes, variant));
  return it->second;
}

const std::string& text_for(Kind kind, size_t nodes, int variant = 0) {
  static std::map<std::tuple<Kind, size_t, int>, std::string> cache;
  auto [it, inserted] = cache.try_emplace({kind, nodes, variant});
  if (inserted) it->second = graph_to_text(graph_for(kind, nodes, variant));
  return it->second;
}

// The synthetic graphs compile at the default frame size with the default scene.
const CompileOptions& synthetic_options() {
  static const CompileOptions options;
  return options;
}

double culled_share(const Plan& plan) {
  if (plan.nodes.empty()) return 0;
  auto culled = std::count_if(plan.nodes.begin(), plan.nodes.end(),
                              [](const PlanNode& n) { return n.state == NodeState::Kind::culled; });
  return static_cast<double>(culled) / static_cast<double>(plan.nodes.size());
}

// ---------------------------------------------------------------------------------------------
// Benchmarks

// recompile: compile() while the previous result lives, freed once the new one is made, as the
// runtime's hot reload replaces a plan. Plain compile frees each result before the next compile,
// so glibc hands the freed heap back to the system and the next compile faults it in again.
enum class Measure { compile, recompile, parse, load_compile };
const char* measure_name(Measure m) {
  switch (m) {
    case Measure::compile: return "compile";
    case Measure::recompile: return "recompile";
    case Measure::parse: return "parse";
    case Measure::load_compile: return "load_compile";
  }
  return "?";
}

// What one untimed run before the timed loop found (the first seed): the same for every repetition.
struct Facts {
  Measure measure = Measure::compile;
  Kind kind = Kind::chain;
  int64_t nodes = 0;
  double culled_share = 0;   // of the plan's nodes; 0 for parse
  HeapUsage heap;            // of one run, over the heap before it (input graph or text excluded)
  int64_t result_bytes = 0;  // of that growth, what the result holds: the Plan, or the parsed Graph
};

std::map<std::string, Facts>& facts() {
  static std::map<std::string, Facts> all;
  return all;
}
std::string key(Measure m, Kind k, int64_t nodes) {
  return std::string(measure_name(m)) + "/" + kind_name(k) + "/" + std::to_string(nodes);
}

// What a run's result holds: the heap's growth since the scope opened, less the free blocks the
// compiler's cache keeps for the next compile (empty when the scope opened).
int64_t result_bytes(const HeapScope& heap) {
  return heap.usage().net_bytes - static_cast<int64_t>(cached_block_bytes());
}

// One run of the measured work. Returns false with `error` set when the graph did not compile.
// With `facts`, notes what the result holds (with `heap`, its bytes) before freeing it. With
// `previous`, the result replaces it (freeing the one before) instead of being freed.
bool run_once(Measure measure, Kind kind, int64_t nodes, int variant, const HeapScope* heap, Facts* facts,
              std::string* error, std::optional<CompileResult>* previous = nullptr) {
  Diagnostics diagnostics;
  std::optional<Graph> parsed;
  const Graph* graph = &graph_for(kind, nodes, variant);
  if (measure == Measure::parse || measure == Measure::load_compile) {
    parsed = parse_graph_text(text_for(kind, nodes, variant), diagnostics);
    benchmark::DoNotOptimize(parsed);
    if (!parsed) {
      if (error) *error = diagnostics.to_string();
      return false;
    }
    if (measure == Measure::parse) {
      if (heap && facts) facts->result_bytes = result_bytes(*heap);
      return true;
    }
    graph = &*parsed;
  }
  CompileResult result = compile(*graph, test::synthetic_registry(), synthetic_options(), diagnostics);
  benchmark::DoNotOptimize(result.plan);
  if (!result.plan) {
    if (error) *error = diagnostics.to_string();
    return false;
  }
  if (facts) facts->culled_share = culled_share(*result.plan);
  if (heap && facts) facts->result_bytes = result_bytes(*heap);
  if (previous) *previous = std::move(result);
  return true;
}

void bench(benchmark::State& state, Measure measure, Kind kind) {
  const int64_t nodes = state.range(0);
  // Build the inputs and the registry (once per process) outside any measurement.
  for (int v = 0; v < variants(kind); ++v) {
    graph_for(kind, nodes, v);
    text_for(kind, nodes, v);
  }
  test::synthetic_registry();

  auto [it, first] = facts().try_emplace(key(measure, kind, nodes));
  Facts& f = it->second;
  if (first) {
    f.measure = measure;
    f.kind = kind;
    f.nodes = nodes;
    std::string error;
    // Kept blocks would hide what the compile takes: start the cache empty, and count what it
    // keeps at the end as heap in use (it is).
    release_cached_blocks();
    HeapScope heap;
    bool ok = run_once(measure, kind, nodes, 0, &heap, &f, &error);
    f.heap = heap.usage();
    if (!ok) {
      facts().erase(it);
      state.SkipWithError(("did not compile: " + error).c_str());
      return;
    }
  }

  std::optional<CompileResult> previous;
  int variant = 0;
  for (auto _ : state) {
    run_once(measure, kind, nodes, variant, nullptr, nullptr, nullptr,
             measure == Measure::recompile ? &previous : nullptr);
    variant = (variant + 1) % variants(kind);
  }

  state.SetComplexityN(nodes);
  state.counters["per_node"] = benchmark::Counter(static_cast<double>(nodes),
                                                  benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  if (measure != Measure::parse) state.counters["culled"] = f.culled_share;
  state.counters["peak_MiB"] = static_cast<double>(f.heap.peak_bytes) / mib;
  state.counters["result_MiB"] = static_cast<double>(f.result_bytes) / mib;
  state.counters["allocs/node"] = static_cast<double>(f.heap.allocations) / static_cast<double>(nodes);
}

void register_benchmarks() {
  for (Measure m : {Measure::compile, Measure::recompile, Measure::parse, Measure::load_compile})
    for (Kind k : {Kind::chain, Kind::random_dag}) {
      auto* b = benchmark::RegisterBenchmark((std::string(measure_name(m)) + "/" + kind_name(k)).c_str(),
                                             [m, k](benchmark::State& s) { bench(s, m, k); });
      for (int64_t n : sizes) b->Arg(n);
      b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
    }
}

// ---------------------------------------------------------------------------------------------
// Collecting the results: the console reporter, which also keeps each benchmark's median.

struct Timing {
  double real_ms = 0, cpu_ms = 0;  // medians over the repetitions (or the one run)
  double cv_percent = -1;          // coefficient of variation of the real time; -1 if one run
  int64_t repetitions = 1;
};

class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  using ConsoleReporter::ConsoleReporter;
  std::map<std::string, Timing> timings;  // by "measure/kind/nodes"

  void ReportRuns(const std::vector<Run>& reports) override {
    ConsoleReporter::ReportRuns(reports);
    for (const Run& run : reports) {
      if (run.error_occurred) continue;
      std::string name = run.run_name.function_name + "/" + run.run_name.args;
      auto to_ms = [&](double t) { return t * 1e3 / benchmark::GetTimeUnitMultiplier(run.time_unit); };
      if (run.run_type == Run::RT_Iteration) {
        // Single runs count only until a median arrives (when repetitions > 1).
        Timing& t = timings[name];
        if (t.repetitions <= 1 && run.repetitions <= 1) t = {to_ms(run.GetAdjustedRealTime()), to_ms(run.GetAdjustedCPUTime()), -1, 1};
      } else if (run.aggregate_name == "median") {
        Timing& t = timings[name];
        t.real_ms = to_ms(run.GetAdjustedRealTime());
        t.cpu_ms = to_ms(run.GetAdjustedCPUTime());
        t.repetitions = run.repetitions;
      } else if (run.aggregate_name == "cv") {
        // A percentage aggregate keeps the ratio itself where a time would be.
        timings[name].cv_percent = 100.0 * run.real_accumulated_time;
      }
    }
  }
};

// ---------------------------------------------------------------------------------------------
// Tables and files

struct Row {
  Facts facts;
  Timing timing;
};

std::vector<Row> rows_of(const CollectingReporter& reporter) {
  std::vector<Row> rows;
  for (Measure m : {Measure::compile, Measure::recompile, Measure::parse, Measure::load_compile})
    for (Kind k : {Kind::chain, Kind::random_dag})
      for (int64_t n : sizes) {
        auto f = facts().find(key(m, k, n));
        auto t = reporter.timings.find(key(m, k, n));
        if (f != facts().end() && t != reporter.timings.end()) rows.push_back({f->second, t->second});
      }
  return rows;
}

void print_timing_table(const std::vector<Row>& rows) {
  std::printf(
      "\nTimings: medians of the repetitions. peak: heap growth during one run over the heap before it (the\n"
      "input graph or text excluded; the compiler's block cache starts empty and what it keeps counts as\n"
      "heap); result: what the Plan (parse: the Graph) holds of it afterwards.\n");
  std::printf("%-13s %-11s %6s %11s %11s %10s %7s %7s %9s %11s %12s\n", "measure", "graph", "nodes", "median ms",
              "cpu ms", "us/node", "cv", "culled", "peak MiB", "result MiB", "allocs/node");
  for (const Row& r : rows) {
    char cv[16] = "-";
    if (r.timing.cv_percent >= 0) std::snprintf(cv, sizeof cv, "%.1f%%", r.timing.cv_percent);
    char culled[16] = "-";
    if (r.facts.measure != Measure::parse) std::snprintf(culled, sizeof culled, "%.1f%%", 100 * r.facts.culled_share);
    std::printf("%-13s %-11s %6lld %11.4f %11.4f %10.3f %7s %7s %9.2f %11.2f %12.1f\n", measure_name(r.facts.measure),
                kind_name(r.facts.kind), static_cast<long long>(r.facts.nodes), r.timing.real_ms, r.timing.cpu_ms,
                1e3 * r.timing.real_ms / static_cast<double>(r.facts.nodes), cv, culled,
                static_cast<double>(r.facts.heap.peak_bytes) / mib, static_cast<double>(r.facts.result_bytes) / mib,
                static_cast<double>(r.facts.heap.allocations) / static_cast<double>(r.facts.nodes));
  }
}

bool write_timing_csv(const std::string& path, const std::vector<Row>& rows, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  // culled_share is empty for parse, which makes no plan; cv_percent is -1 after a single run.
  out << "measure,graph,nodes,median_ms,median_cpu_ms,ms_per_node,culled_share,peak_mib,result_mib,allocations,"
         "repetitions,cv_percent\n";
  char line[512], culled[32];
  for (const Row& r : rows) {
    culled[0] = 0;
    if (r.facts.measure != Measure::parse) std::snprintf(culled, sizeof culled, "%.4f", r.facts.culled_share);
    std::snprintf(line, sizeof line, "%s,%s,%lld,%.6g,%.6g,%.6g,%s,%.4f,%.4f,%llu,%lld,%.2f\n", measure_name(r.facts.measure),
                  kind_name(r.facts.kind), static_cast<long long>(r.facts.nodes), r.timing.real_ms, r.timing.cpu_ms,
                  r.timing.real_ms / static_cast<double>(r.facts.nodes), culled,
                  static_cast<double>(r.facts.heap.peak_bytes) / mib, static_cast<double>(r.facts.result_bytes) / mib,
                  static_cast<unsigned long long>(r.facts.heap.allocations), static_cast<long long>(r.timing.repetitions),
                  r.timing.cv_percent);
    out << line;
  }
  return static_cast<bool>(out);
}

// Per-phase times from CompileResult::timings: the median of many compiles for each phase,
// plus what compile() spent outside the phases (moving and freeing the IRs between phases) and
// what freeing the result costs afterwards.
struct PhaseColumn {
  Kind kind;
  int64_t nodes;
  int runs = 0;
  std::vector<std::pair<std::string, double>> phases;  // median ms
  double total_ms = 0;                                 // median wall time of compile() itself
  double free_ms = 0;                                  // median time to destroy the CompileResult
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

constexpr int64_t phase_sizes[] = {100, 1000, 10000};

// `runs` compiles of the 10,000-node graphs; smaller graphs get more, as they are quicker.
std::vector<PhaseColumn> measure_phases(int runs) {
  using clock = std::chrono::steady_clock;
  auto ms_since = [](clock::time_point start) {
    return std::chrono::duration<double, std::milli>(clock::now() - start).count();
  };
  std::vector<PhaseColumn> columns;
  for (Kind kind : {Kind::chain, Kind::random_dag})
    for (int64_t nodes : phase_sizes) {
      for (int v = 0; v < variants(kind); ++v) graph_for(kind, nodes, v);
      PhaseColumn column{kind, nodes, runs * (nodes <= 100 ? 10 : nodes <= 1000 ? 3 : 1), {}, 0, 0};
      std::vector<std::vector<double>> samples;
      std::vector<double> totals, frees;
      for (int run = 0; run < column.runs; ++run) {
        Diagnostics diagnostics;
        auto start = clock::now();
        const Graph& graph = graph_for(kind, nodes, run % variants(kind));
        CompileResult result = compile(graph, test::synthetic_registry(), synthetic_options(), diagnostics);
        totals.push_back(ms_since(start));
        if (!result.plan) break;
        if (samples.empty()) {
          samples.resize(result.timings.size());
          for (const auto& t : result.timings) column.phases.emplace_back(t.phase, 0);
        }
        for (size_t p = 0; p < result.timings.size() && p < samples.size(); ++p)
          samples[p].push_back(result.timings[p].milliseconds);
        start = clock::now();
        result = CompileResult();  // frees the plan
        frees.push_back(ms_since(start));
      }
      for (size_t p = 0; p < column.phases.size(); ++p) column.phases[p].second = median(samples[p]);
      column.total_ms = median(totals);
      column.free_ms = median(frees);
      columns.push_back(std::move(column));
    }
  return columns;
}

// One table per graph kind: a row per phase, a column per size, the growth between sizes.
void print_phase_table(const std::vector<PhaseColumn>& columns) {
  for (Kind kind : {Kind::chain, Kind::random_dag}) {
    std::vector<const PhaseColumn*> cs;
    for (const auto& c : columns)
      if (c.kind == kind && !c.phases.empty()) cs.push_back(&c);
    if (cs.size() != std::size(phase_sizes)) continue;
    std::printf("\nWhere compile() spends its time, %s (CompileResult::timings; median ms of %d, %d, %d compiles)\n",
                kind_name(kind), cs[0]->runs, cs[1]->runs, cs[2]->runs);
    std::printf("%-20s %11s %11s %11s %9s %9s %9s\n", "phase", "100 nodes", "1k nodes", "10k nodes", "1k/100",
                "10k/1k", "share");
    auto row = [&](const std::string& name, auto value) {
      double v[3] = {value(*cs[0]), value(*cs[1]), value(*cs[2])};
      auto growth = [](double a, double b) { return a > 0 ? b / a : 0.0; };
      std::printf("%-20s %11.4f %11.4f %11.4f %8.1fx %8.1fx %8.1f%%\n", name.c_str(), v[0], v[1], v[2],
                  growth(v[0], v[1]), growth(v[1], v[2]), cs[2]->total_ms > 0 ? 100 * v[2] / cs[2]->total_ms : 0.0);
    };
    for (size_t p = 0; p < cs[0]->phases.size(); ++p)
      row(cs[0]->phases[p].first, [p](const PhaseColumn& c) { return p < c.phases.size() ? c.phases[p].second : 0.0; });
    row("outside phases", [](const PhaseColumn& c) {
      double sum = 0;
      for (const auto& [name, ms] : c.phases) sum += ms;
      return std::max(0.0, c.total_ms - sum);
    });
    row("compile() total", [](const PhaseColumn& c) { return c.total_ms; });
    row("freeing the result", [](const PhaseColumn& c) { return c.free_ms; });
  }
  std::printf("share: of compile() total at 10k nodes. The benchmarks time compile() and freeing its result, as a\n"
              "caller pays both; each phase's time includes the page faults of the memory it touches first.\n");
}

bool write_phase_csv(const std::string& path, const std::vector<PhaseColumn>& columns, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  out << "graph,nodes,phase,median_ms\n";
  for (const auto& c : columns) {
    for (const auto& [phase, ms] : c.phases) out << kind_name(c.kind) << ',' << c.nodes << ',' << phase << ',' << ms << '\n';
    out << kind_name(c.kind) << ',' << c.nodes << ",compile_total," << c.total_ms << '\n';
    out << kind_name(c.kind) << ',' << c.nodes << ",free_result," << c.free_ms << '\n';
  }
  return static_cast<bool>(out);
}

// ---------------------------------------------------------------------------------------------
// Targets of the issue. Each prints one line; a target whose numbers were not measured in this
// run (filtered out) says so.

void print_targets(const std::vector<Row>& rows, const std::vector<MemoryRow>& memory, bool timed) {
  std::printf("\nTargets (medians of this run; timings on a shared machine are noisy)\n");
  auto find = [&](Measure m, Kind k, int64_t n) -> const Row* {
    for (const Row& r : rows)
      if (r.facts.measure == m && r.facts.kind == k && r.facts.nodes == n) return &r;
    return nullptr;
  };
  auto line = [](const char* what, std::optional<bool> met, const std::string& measured) {
    std::printf("target %-66s %-12s %s\n", what, !met ? "NOT MEASURED" : *met ? "MET" : "NOT MET", measured.c_str());
  };
  char buf[256];

  if (timed) {
    for (auto [n, limit] : {std::pair<int64_t, double>{1000, 1.0}, {10000, 15.0}}) {
      std::string what = "compile random DAG of " + std::string(n == 1000 ? "1,000" : "10,000") + " nodes < " +
                         (limit == 1.0 ? "1" : "15") + " ms median:";
      if (const Row* r = find(Measure::compile, Kind::random_dag, n)) {
        std::snprintf(buf, sizeof buf, "%.3f ms (cpu %.3f ms)", r->timing.real_ms, r->timing.cpu_ms);
        std::string measured = buf;
        if (const Row* re = find(Measure::recompile, Kind::random_dag, n)) {
          std::snprintf(buf, sizeof buf, "; recompile %.3f ms", re->timing.real_ms);
          measured += buf;
        }
        line(what.c_str(), r->timing.real_ms < limit, measured);
      } else {
        line(what.c_str(), std::nullopt, "");
      }
    }
    for (Kind k : {Kind::random_dag, Kind::chain}) {
      std::string what = std::string("near-linear, 10x nodes <= 12x time (compile ") + kind_name(k) + "):";
      double worst = 0;
      std::string where;
      bool any = false;
      for (size_t i = 0; i + 1 < std::size(sizes); ++i) {
        const Row* a = find(Measure::compile, k, sizes[i]);
        const Row* b = find(Measure::compile, k, sizes[i + 1]);
        if (!a || !b || a->timing.real_ms <= 0) continue;
        double ratio = b->timing.real_ms / a->timing.real_ms;
        std::snprintf(buf, sizeof buf, "%s%lld->%lld %.1fx", any ? ", " : "", static_cast<long long>(sizes[i]),
                      static_cast<long long>(sizes[i + 1]), ratio);
        where += buf;
        any = true;
        worst = std::max(worst, ratio);
      }
      line(what.c_str(), any ? std::optional<bool>(worst <= 12.0) : std::nullopt, where);
    }
    {
      const Row* chain = find(Measure::compile, Kind::chain, 10000);
      const Row* dag = find(Measure::compile, Kind::random_dag, 10000);
      double worst = 0;
      std::string measured;
      for (const Row* r : {chain, dag}) {
        if (!r) continue;
        double peak = static_cast<double>(r->facts.heap.peak_bytes) / mib;
        worst = std::max(worst, peak);
        std::snprintf(buf, sizeof buf, "%s%s %.1f MiB", measured.empty() ? "" : ", ", kind_name(r->facts.kind), peak);
        measured += buf;
      }
      if (const Row* r = find(Measure::load_compile, Kind::random_dag, 10000)) {
        std::snprintf(buf, sizeof buf, " (load+compile random_dag %.1f MiB)", static_cast<double>(r->facts.heap.peak_bytes) / mib);
        measured += buf;
      }
      line("compiling 10,000 nodes peaks < 64 MiB of heap:", chain || dag ? std::optional<bool>(worst < 64.0) : std::nullopt,
           measured);
    }
  }
  const MemoryRow* def = nullptr;
  for (const auto& m : memory)
    if (m.example == "default.json" && m.frame.width == 1920 && m.frame.height == 1080) def = &m;
  if (def && def->error.empty()) {
    std::snprintf(buf, sizeof buf, "%.1f%% (%s -> %s)", def->saving_percent(), format_bytes(def->unaliased).c_str(),
                  format_bytes(def->aliased).c_str());
    line("aliasing saves >= 40% of default.json transient at 1920x1080:", def->saving_percent() >= 40.0, buf);
  } else {
    line("aliasing saves >= 40% of default.json transient at 1920x1080:", std::nullopt,
         def ? "default.json did not compile" : "");
  }
}

// ---------------------------------------------------------------------------------------------

struct Args {
  std::string results_dir = LUMAGRAPH_BINARY_DIR "/bench-results";
  std::string examples_dir = LUMAGRAPH_SOURCE_DIR "/examples";
  int phase_runs = 15;
  bool benchmarks = true, phases = true, memory = true;
};

const char* const usage =
    "usage: lumagraph-bench-compile [options] [--benchmark_* flags]\n"
    "  --results-dir DIR    where the CSV files go (default " LUMAGRAPH_BINARY_DIR "/bench-results)\n"
    "  --examples-dir DIR   graphs for the memory table (default " LUMAGRAPH_SOURCE_DIR "/examples)\n"
    "  --phase-runs N       compiles of each 10,000-node graph for the per-phase table (default 15)\n"
    "  --memory-table       the transient-memory table of the examples, and no benchmarks\n"
    "  --phase-table        the per-phase table, and no benchmarks (both flags: both tables)\n"
    "Without either: the Google Benchmark run, then both tables and the targets.\n"
    "Google Benchmark's flags pass through: --benchmark_filter=REGEX, --benchmark_repetitions=N (medians\n"
    "need N >= 2), --benchmark_min_time=SECONDS, --benchmark_out=FILE, ...\n";

// Takes this program's own options out of argv, leaving Google Benchmark's.
std::optional<Args> parse_args(int& argc, char** argv) {
  Args args;
  bool only_memory = false, only_phases = false;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name, std::string& out) {
      std::string prefix = std::string(name) + "=";
      if (a == name && i + 1 < argc) return out = argv[++i], true;
      if (a.rfind(prefix, 0) == 0) return out = a.substr(prefix.size()), true;
      return false;
    };
    std::string runs;
    if (a == "-h" || a == "--help") {
      std::fputs(usage, stdout);
      return std::nullopt;
    } else if (value("--results-dir", args.results_dir) || value("--examples-dir", args.examples_dir)) {
    } else if (value("--phase-runs", runs)) {
      args.phase_runs = std::max(1, std::atoi(runs.c_str()));
    } else if (a == "--memory-table") {
      only_memory = true;
    } else if (a == "--phase-table") {
      only_phases = true;
    } else {
      argv[kept++] = argv[i];
    }
  }
  if (only_memory || only_phases) args.benchmarks = false, args.memory = only_memory, args.phases = only_phases;
  argc = kept;
  argv[argc] = nullptr;
  return args;
}

int run(int argc, char** argv) {
  std::optional<Args> args = parse_args(argc, argv);
  if (!args) return 0;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  std::error_code ec;
  std::filesystem::create_directories(args->results_dir, ec);
  if (ec) {
    std::fprintf(stderr, "cannot create %s: %s\n", args->results_dir.c_str(), ec.message().c_str());
    return 1;
  }
  std::vector<std::string> written, failed;
  auto wrote = [&](bool ok, const std::string& path, const std::string& error) {
    (ok ? written : failed).push_back(ok ? path : error);
  };

  std::vector<Row> rows;
  if (args->benchmarks) {
    register_benchmarks();
    const test::RandomDagOptions dag = dag_options(0);
    char context[128];
    std::snprintf(context, sizeof context, "dead %g, history %g, window %zu, seeds %llu to %d, in turn",
                  dag.dead_fraction, dag.history_fraction, dag.window, static_cast<unsigned long long>(dag.seed),
                  dag_seeds);
    benchmark::AddCustomContext("random_dag", context);
    CollectingReporter reporter(isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_ColorTabular
                                                       : benchmark::ConsoleReporter::OO_Tabular);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    rows = rows_of(reporter);
    print_timing_table(rows);
    std::string path = args->results_dir + "/compile_times.csv", error;
    wrote(write_timing_csv(path, rows, &error), path, error);
  }
  if (args->phases) {
    std::vector<PhaseColumn> columns = measure_phases(args->phase_runs);
    print_phase_table(columns);
    std::string path = args->results_dir + "/compile_phases.csv", error;
    wrote(write_phase_csv(path, columns, &error), path, error);
  }
  std::vector<MemoryRow> memory;
  if (args->memory) {
    memory = measure_memory(args->examples_dir, {{1920, 1080}, {1280, 720}});
    print_memory_table(stdout, memory);
    std::string path = args->results_dir + "/memory_aliasing.csv", error;
    wrote(write_memory_csv(path, memory, &error), path, error);
  }
  if (args->benchmarks || args->memory) print_targets(rows, memory, args->benchmarks);

  std::printf("\n");
  for (const auto& path : written) std::printf("wrote %s\n", path.c_str());
  for (const auto& error : failed) std::fprintf(stderr, "error: %s\n", error.c_str());
  return failed.empty() ? 0 : 1;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) { return lg::bench::run(argc, argv); }
