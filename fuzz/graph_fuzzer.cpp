// libFuzzer harness: a graph file's text through the parser and compile() with the built-in
// node schemas, for the default scene and for an empty one (which bypasses most nodes). Any input
// must end in a plan with no errors or in located errors; never a crash, a hang or silence.
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_input.h"
#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace {

void compile_for(const lg::Graph& graph, const lg::SceneSummary& scene) {
  lg::Diagnostics diagnostics("fuzz.json");
  lg::CompileOptions options;
  options.scene = scene;
  const lg::CompileResult result = lg::compile(graph, lg::builtin_registry(), options, diagnostics);
  if (result.plan.has_value() == diagnostics.has_errors()) {
    std::fprintf(stderr, "compile() gave %s with %zu errors\n%s", result.plan ? "a plan" : "no plan",
                 diagnostics.error_count(), diagnostics.to_string().c_str());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lg::Diagnostics diagnostics("fuzz.json");
  const std::optional<lg::Graph> graph = lg::parse_graph_text(lg::fuzz::as_text(data, size), diagnostics);
  if (graph.has_value() == diagnostics.has_errors()) {
    std::fprintf(stderr, "parse_graph_text() disagrees with its diagnostics\n%s", diagnostics.to_string().c_str());
    std::abort();
  }
  if (!graph) return 0;
  compile_for(*graph, lg::default_scene_summary());
  compile_for(*graph, lg::SceneSummary{});
  return 0;
}
