// The environment of a graph for the CPU tracers (graph_environment.h).
#include "cli/graph_environment.h"

#include <cstdio>
#include <filesystem>

#include "cli/graph_input.h"
#include "nodes/builtin_schemas.h"
#include "nodes/common/node_params.h"
#include "nodes/env/load/env_load_kernel.h"
#include "runtime/image/image_file.h"

namespace lg::cli {
namespace {

PathEnvironment plan_environment(const Plan& plan, const char* command, bool& cull_backfaces) {
  for (const PlanNode& node : plan.nodes)
    if (node.type == "scene.gbuffer" && node.state == NodeState::Kind::active)
      cull_backfaces = param_bool(node, "cull_backfaces");
  for (const PlanNode& node : plan.nodes) {
    if (node.state != NodeState::Kind::active) continue;
    if (node.type == "env.load") {
      ImageData image = load_image(param_string(node, "path"));
      const uint64_t non_finite = sanitize_equirect(image.rgba, param_number(node, "intensity"));
      if (non_finite)
        std::fprintf(stderr, "lumagraph %s: %llu non-finite texels of %s replaced by 0\n", command,
                     static_cast<unsigned long long>(non_finite), param_string(node, "path").c_str());
      return PathEnvironment::image(Equirect{image.width, image.height, std::move(image.rgba)});
    }
    if (node.type == "env.sky")
      return PathEnvironment::sky({glm::dvec3(param_float3(node, "sun_direction")), param_number(node, "sun_intensity"),
                                   param_number(node, "turbidity")});
  }
  return PathEnvironment::none();
}

}  // namespace

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
  return plan_environment(*compiled.plan, command, cull_backfaces);
}

}  // namespace lg::cli
