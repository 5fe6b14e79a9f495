#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/commands.h"
#include "cli/graph_input.h"
#include "graph/graph_io.h"
#include "graph/json_writer.h"
#include "graph/plan_format.h"
#include "nodes/builtin_schemas.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph compile [GRAPH] [options]

Compiles a graph against a scene and prints the plan: passes in order, nodes bypassed or
culled and why, resources with lifetimes and memory offsets, barriers. With no GRAPH, the
embedded default graph (examples/default.json).

options:
  --scene FILE        scene summary (JSON) to specialize for; default: the embedded scene
  --size WxH          frame size in pixels (default 1280x720)
  --format FORMAT     text (default), json or dot (Graphviz)
  --asset-root DIR    allow file paths in params under DIR (repeatable; default: the
                      graph file's folder)
  --no-alias          give every transient resource its own memory (for comparison)
  --timings           print each compiler phase's time on stderr
  --dump-phases DIR   write each phase's intermediate result to DIR as JSON

exit status: 0 compiled, 1 usage error, 2 invalid graph or scene (errors on stderr as
file:line:col: error: message (json pointer))
)";

void write_dumps(const std::string& dir, const Graph& graph, const CompileResult& result) {
  std::filesystem::create_directories(dir);
  auto write = [&](int index, const std::string& phase, const JsonValue& value) {
    char name[64];
    std::snprintf(name, sizeof name, "%02d-%s.json", index, phase.c_str());
    std::string error;
    if (!write_file_atomically((std::filesystem::path(dir) / name).string(), write_json(value), &error))
      std::fprintf(stderr, "lumagraph compile: %s\n", error.c_str());
  };
  write(1, "parse", graph_to_json(graph));
  int index = 2;
  for (const auto& [phase, value] : result.dumps) write(index++, phase, value);
  if (result.plan) write(index, "plan", plan_to_json(*result.plan));
}

}  // namespace

int compile_command(const std::vector<std::string>& argv) {
  std::string error;
  auto args = parse_args(argv, graph_arg_spec(), &error);
  if (!args) return usage_error("compile", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  if (args->positional.size() > 1) return usage_error("compile", "expected one graph file, got " + std::to_string(args->positional.size()));
  std::string format = args->value("--format").value_or("text");
  if (format != "text" && format != "json" && format != "dot")
    return usage_error("compile", "--format must be text, json or dot; got '" + format + "'");

  Diagnostics diagnostics;
  CompileOptions options;
  if (auto bad = read_compile_options(*args, options, diagnostics)) return usage_error("compile", *bad);
  options.keep_dumps = args->value("--dump-phases").has_value();

  auto start = std::chrono::steady_clock::now();
  auto graph = diagnostics.has_errors() ? std::nullopt : load_graph_argument(*args, diagnostics);
  double parse_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  CompileResult result;
  if (graph) result = compile(*graph, builtin_registry(), options, diagnostics);
  diagnostics.sort_by_position();
  std::fputs(diagnostics.to_string().c_str(), stderr);

  if (args->has("--timings")) {
    double total = parse_ms;
    std::fprintf(stderr, "%-12s %9.3f ms\n", "parse", parse_ms);
    for (const auto& t : result.timings) {
      std::fprintf(stderr, "%-12s %9.3f ms\n", t.phase.c_str(), t.milliseconds);
      total += t.milliseconds;
    }
    std::fprintf(stderr, "%-12s %9.3f ms\n", "total", total);
  }
  if (graph && args->value("--dump-phases")) write_dumps(*args->value("--dump-phases"), *graph, result);
  if (!result.plan) {
    std::fprintf(stderr, "lumagraph compile: %zu error%s\n", diagnostics.error_count(), diagnostics.error_count() == 1 ? "" : "s");
    return exit_invalid;
  }
  if (format == "json") std::fputs(write_json(plan_to_json(*result.plan)).c_str(), stdout);
  else if (format == "dot") std::fputs(plan_to_dot(*result.plan).c_str(), stdout);
  else std::fputs(plan_to_text(*result.plan).c_str(), stdout);
  return exit_ok;
}

}  // namespace lg::cli
