#include "cli/graph_input.h"

#include <cstdio>
#include <span>

#include "cli/embedded_examples.h"
#include "graph/graph_io.h"
#include "graph/scene_summary.h"

namespace lg::cli {

ArgSpec graph_arg_spec() {
  return {{"--timings", "--no-alias", "--help"},
          {"--scene", "--size", "--asset-root", "--format", "--dump-phases"},
          {"--asset-root"}};
}

std::optional<Graph> load_graph_argument(const Args& args, Diagnostics& diagnostics) {
  if (!args.positional.empty()) return load_graph_file(args.positional.front(), diagnostics);
  for (const EmbeddedFile& file : embedded_examples()) {
    if (file.path != "examples/default.json") continue;
    diagnostics.set_file("<embedded " + std::string(file.path) + ">");
    auto graph = parse_graph_text(file.text, diagnostics);
    if (graph) graph->file.clear();  // embedded: no folder for relative paths
    return graph;
  }
  diagnostics.error({}, "", "no embedded default graph in this build");
  return std::nullopt;
}

std::optional<Graph> load_graph_argument_or_print(const Args& args) {
  Diagnostics diagnostics;
  std::optional<Graph> graph = load_graph_argument(args, diagnostics);
  if (!graph) {
    diagnostics.sort_by_position();
    std::fputs(diagnostics.to_string().c_str(), stderr);
  }
  return graph;
}

std::optional<std::string> read_frame_size(const Args& args, FrameSize& frame) {
  if (auto size = args.value("--size")) {
    unsigned w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(size->c_str(), "%ux%u%c", &w, &h, &tail) != 2 || w == 0 || h == 0 || w > 16384 || h > 16384)
      return "--size expects WIDTHxHEIGHT, each from 1 to 16384, for example 1920x1080; got '" + *size + "'";
    frame = {w, h};
  }
  return std::nullopt;
}

std::optional<std::string> read_compile_options(const Args& args, CompileOptions& options, Diagnostics& diagnostics) {
  if (auto bad = read_frame_size(args, options.frame)) return bad;
  options.roots.roots = args.values("--asset-root");
  options.alias.enabled = !args.has("--no-alias");
  if (auto scene = args.value("--scene")) {
    Diagnostics scene_diagnostics(*scene);
    auto summary = load_scene_summary(*scene, scene_diagnostics);
    for (const auto& d : scene_diagnostics.items()) diagnostics.add(d);
    if (!summary) return std::nullopt;
    options.scene = *summary;
    if (options.scene.name.empty()) options.scene.name = *scene;
  }
  return std::nullopt;
}

}  // namespace lg::cli
