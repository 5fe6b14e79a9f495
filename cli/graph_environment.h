// The environment a graph lights a scene with, for the commands that trace on the CPU (`reference`
// and `bake --mode probes`): the graph of --graph (default: the embedded default graph), its
// env.load nodes pointed at --env's file when given, compiled for the scene; of what the plan
// keeps, the first env.load (the file) or env.sky (sky and sun), none when it keeps neither.
#pragma once

#include <optional>

#include "cli/args.h"
#include "graph/compiler.h"
#include "nodes/gi/path_tracer/path_scene.h"
#include "runtime/scene/scene_view.h"

namespace lg::cli {

// nullopt: the graph did not load or compile, and its diagnostics are on stderr. Sets
// `cull_backfaces` as the plan's scene.gbuffer does (unchanged without one). Throws what loading
// the environment's image throws; `command` names the command in warnings.
std::optional<PathEnvironment> load_graph_environment(const Args& args, const SceneView& view, FrameSize frame,
                                                      const char* command, bool& cull_backfaces);

}  // namespace lg::cli
