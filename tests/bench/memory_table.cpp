#include "tests/bench/memory_table.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "graph/plan_format.h"
#include "nodes/builtin_schemas.h"

namespace lg::bench {
namespace {

std::optional<Plan> compile_example(const Graph& graph, FrameSize frame, bool aliasing, std::string* error) {
  CompileOptions options;
  options.frame = frame;
  options.alias.enabled = aliasing;
  Diagnostics diagnostics(graph.file);
  CompileResult result = compile(graph, builtin_registry(), options, diagnostics);
  if (!result.plan) *error = diagnostics.to_string();
  return std::move(result.plan);
}

double mib(uint64_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

}  // namespace

double MemoryRow::saving_percent() const {
  return unaliased == 0 ? 0.0 : 100.0 * (1.0 - static_cast<double>(aliased) / static_cast<double>(unaliased));
}

std::vector<MemoryRow> measure_memory(const std::string& examples_dir, const std::vector<FrameSize>& frames) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(examples_dir, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());

  std::vector<MemoryRow> rows;
  for (const auto& file : files) {
    Diagnostics load_diagnostics;
    std::optional<Graph> graph = load_graph_file(file.string(), load_diagnostics);
    for (FrameSize frame : frames) {
      MemoryRow row;
      row.example = file.filename().string();
      row.frame = frame;
      if (!graph) {
        row.error = load_diagnostics.to_string();
        rows.push_back(row);
        continue;
      }
      std::optional<Plan> with = compile_example(*graph, frame, true, &row.error);
      std::optional<Plan> without = with ? compile_example(*graph, frame, false, &row.error) : std::nullopt;
      if (with && without) {
        row.aliased = with->memory.transient;
        row.unaliased = without->memory.transient;
        row.unaliased_sum = with->memory.transient_unaliased;
        row.persistent = with->memory.persistent;
        std::vector<uint64_t> alive(with->passes.size() + 1, 0);
        for (const PlanResource& r : with->resources) {
          if (r.placement.block != 0) continue;
          ++row.transient_resources;
          for (int t = r.first; t >= 0 && t <= r.last && t < static_cast<int>(alive.size()); ++t) alive[t] += r.desc.bytes;
        }
        row.live_peak = *std::max_element(alive.begin(), alive.end());
      }
      rows.push_back(row);
    }
  }
  return rows;
}

void print_memory_table(std::FILE* out, const std::vector<MemoryRow>& rows) {
  std::fprintf(out, "\nTransient memory of examples/*.json (built-in registry, default scene)\n");
  std::fprintf(out, "%-14s %-10s %10s %12s %12s %8s %12s %12s %12s\n", "example", "frame", "transient", "unaliased",
               "aliased", "saving", "live peak", "sum", "persistent");
  for (const auto& r : rows) {
    std::string frame = std::to_string(r.frame.width) + "x" + std::to_string(r.frame.height);
    if (!r.error.empty()) {
      std::fprintf(out, "%-14s %-10s  did not compile:\n%s\n", r.example.c_str(), frame.c_str(), r.error.c_str());
      continue;
    }
    std::fprintf(out, "%-14s %-10s %10d %12s %12s %7.1f%% %12s %12s %12s\n", r.example.c_str(), frame.c_str(),
                 r.transient_resources, format_bytes(r.unaliased).c_str(), format_bytes(r.aliased).c_str(),
                 r.saving_percent(), format_bytes(r.live_peak).c_str(), format_bytes(r.unaliased_sum).c_str(),
                 format_bytes(r.persistent).c_str());
  }
  std::fprintf(out,
               "transient: resources in block 0. unaliased: block 0 compiled with aliasing off; aliased: with it on\n"
               "(Plan::memory.transient); live peak: most transient bytes alive during one pass, the floor for any\n"
               "aliasing; sum: Plan::memory.transient_unaliased (sizes added up, no alignment padding).\n");
}

bool write_memory_csv(const std::string& path, const std::vector<MemoryRow>& rows, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    *error = "cannot write " + path;
    return false;
  }
  out << "example,width,height,transient_resources,unaliased_bytes,aliased_bytes,saving_percent,live_peak_bytes,"
         "unaliased_sum_bytes,persistent_bytes,unaliased_mib,aliased_mib,error\n";
  char line[512];
  for (const auto& r : rows) {
    bool ok = r.error.empty();
    std::snprintf(line, sizeof line, "%s,%u,%u,%d,%llu,%llu,%.2f,%llu,%llu,%llu,%.3f,%.3f,%s\n", r.example.c_str(),
                  r.frame.width, r.frame.height, r.transient_resources, static_cast<unsigned long long>(r.unaliased),
                  static_cast<unsigned long long>(r.aliased), ok ? r.saving_percent() : 0.0,
                  static_cast<unsigned long long>(r.live_peak),
                  static_cast<unsigned long long>(r.unaliased_sum), static_cast<unsigned long long>(r.persistent),
                  mib(r.unaliased), mib(r.aliased), ok ? "" : "did not compile");
    out << line;
  }
  return static_cast<bool>(out);
}

}  // namespace lg::bench
