// The environment of a graph for the CPU tracers (graph_environment.h).
#include "cli/graph_environment.h"

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/graph_input.h"
#include "nodes/builtin_schemas.h"
#include "nodes/gi/path_tracer/plan_environment.h"

namespace lg::cli {

std::optional<PathEnvironment> load_graph_environment(const Args& args, const SceneView& view, FrameSize frame,
                                                      const char* command, bool& cull_backfaces) {
  Args graph_args = args;
  graph_args.positional.clear();
  if (auto graph_path = args.value("--graph")) graph_args.positional.push_back(*graph_path);
  Diagnostics diagnostics;
  std::optional<Graph> graph = load_graph_argument(graph_args, diagnostics);
  CompileOptions compile_options;
  compile_options.scene = view.summary();
  compile_options.frame = frame;
  compile_options.roots.roots = args.values("--asset-root");
  if (graph && args.value("--env")) {
    bool used = false;
    for (GraphNode& node : graph->nodes)
      if (node.type == "env.load") {
        node.params.set("path", std::filesystem::absolute(*args.value("--env")).string());
        used = true;
      }
    if (!used)
      std::fprintf(stderr, "lumagraph %s: warning: --env is not used: the graph has no env.load node\n", command);
  }
  CompileResult compiled;
  if (graph) compiled = compile(*graph, builtin_registry(), compile_options, diagnostics);
  if (!compiled.plan) {
    diagnostics.sort_by_position();
    std::fputs(diagnostics.to_string().c_str(), stderr);
    return std::nullopt;
  }
  cull_backfaces = plan_culls_backfaces(*compiled.plan, cull_backfaces);
  return plan_environment(*compiled.plan, view.has_environment, ("lumagraph " + std::string(command)).c_str());
}

}  // namespace lg::cli
