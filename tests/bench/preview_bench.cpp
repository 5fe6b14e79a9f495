// How soon the editor's live preview shows a parameter edit: the default graph on the default
// world at 640x360 through RuntimePreview (compile for the edited graph, a new executor that
// takes the unchanged static results from the last one, one frame, readback to float pixels),
// with the device already up
// as it is in a running editor. Each iteration edits the tone mapper's exposure. The queue hop
// to the UI thread is not included (microseconds). The target is under 1 s on lavapipe.
#include <benchmark/benchmark.h>

#include "editor/runtime_preview.h"
#include "graph/graph_io.h"

namespace {

lg::Graph default_graph() {
  lg::Diagnostics d;
  std::optional<lg::Graph> graph = lg::load_graph_file(LUMAGRAPH_SOURCE_DIR "/examples/default.json", d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

void PreviewAfterParamEdit(benchmark::State& state) {
  lg::editor::RuntimePreview preview;
  lg::Graph graph = default_graph();
  QString error;
  if (preview.render(graph, {640, 360}, {}, &error).empty()) state.SkipWithError(error.toStdString().c_str());
  int edit = 0;
  for (auto _ : state) {
    for (lg::GraphNode& node : graph.nodes)
      if (node.id == "tonemap") node.params.set("exposure", -1.5 + 0.1 * (++edit % 10));
    lg::editor::PreviewImage image = preview.render(graph, {640, 360}, {}, &error);
    benchmark::DoNotOptimize(image);
  }
}
BENCHMARK(PreviewAfterParamEdit)->Unit(benchmark::kMillisecond)->Iterations(5)->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
