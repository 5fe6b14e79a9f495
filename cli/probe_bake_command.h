// `lumagraph bake --mode probes` and the merge of its parts: the probes of every irradiance
// volume of a scene baked with the path tracer's transport in the graph's environment, whole or
// one chunk at a time (docs/probe-format.md, docs/baking.md). bake_command dispatches here.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"
#include "runtime/scene/load_world.h"

namespace lg::cli {

// Bakes the probes of the scene file `input`, loaded with `load_options`, into `out`; returns the
// exit status.
int probe_bake_command(const Args& args, const std::string& input, const WorldLoadOptions& load_options,
                       const std::string& out);

// Merges the .lgprobes parts into `out`; returns the exit status.
int probe_merge_command(const std::vector<std::string>& parts, const std::string& out);

}  // namespace lg::cli
