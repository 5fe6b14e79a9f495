#include <cstdio>

#include "cli/commands.h"
#include "cli/graph_input.h"
#include "nodes/builtin_schemas.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph validate GRAPH [--scene FILE] [--size WxH] [--asset-root DIR]...

Checks a graph file: JSON syntax, format version, node types, ports, link types, params
(type, range, enum, file paths), required inputs, cycles, and that it compiles. Every
error is reported as file:line:col: error: message (json pointer).

exit status: 0 valid, 1 usage error, 2 invalid
)";

}  // namespace

int validate_command(const std::vector<std::string>& argv) {
  std::string error;
  ArgSpec spec = graph_arg_spec();
  spec.flags = {"--help"};
  spec.options.erase("--format");
  spec.options.erase("--dump-phases");
  auto args = parse_args(argv, spec, &error);
  if (!args) return usage_error("validate", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  if (args->positional.size() != 1) return usage_error("validate", "expected one graph file");

  Diagnostics diagnostics;
  CompileOptions options;
  if (auto bad = read_compile_options(*args, options, diagnostics)) return usage_error("validate", *bad);
  auto graph = diagnostics.has_errors() ? std::nullopt : load_graph_argument(*args, diagnostics);
  CompileResult result;
  if (graph) result = compile(*graph, builtin_registry(), options, diagnostics);
  diagnostics.sort_by_position();
  std::fputs(diagnostics.to_string().c_str(), stderr);
  if (!result.plan) {
    std::fprintf(stderr, "%s: invalid (%zu error%s)\n", args->positional.front().c_str(), diagnostics.error_count(),
                 diagnostics.error_count() == 1 ? "" : "s");
    return exit_invalid;
  }
  std::printf("%s: valid (%zu nodes, %zu links, %zu passes)\n", args->positional.front().c_str(), graph->nodes.size(),
              graph->links.size(), result.plan->passes.size());
  return exit_ok;
}

}  // namespace lg::cli
