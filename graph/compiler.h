// Runs the compiler phases in order — resolve, validate, specialize, cull, lower, schedule,
// lifetimes, alias, synchronize — and assembles the Plan. Each phase lives in graph/compiler/
// and can be called alone; this file only wires them, times them and keeps their dumps.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/asset_paths.h"
#include "graph/compiler/alias.h"
#include "graph/compiler/lower.h"
#include "graph/diagnostics.h"
#include "graph/graph.h"
#include "graph/plan.h"
#include "graph/registry.h"
#include "graph/scene_summary.h"

namespace lg {

struct CompileOptions {
  SceneSummary scene = default_scene_summary();
  FrameSize frame;
  AssetRoots roots;
  AliasOptions alias;
  bool keep_dumps = false;  // fill CompileResult::dumps with every phase's IR
  // Write every optional output (gi.lpv's volume), linked or not: `render --dump` keeps them.
  bool keep_optional_outputs = false;
};

struct PhaseTiming {
  std::string phase;
  double milliseconds = 0;
};

struct CompileResult {
  std::optional<Plan> plan;  // nullopt when there were errors
  std::vector<PhaseTiming> timings;
  std::vector<std::pair<std::string, JsonValue>> dumps;  // (phase, IR) in phase order
};

CompileResult compile(const Graph& graph, const Registry& registry, const CompileOptions& options,
                      Diagnostics& diagnostics);

}  // namespace lg
