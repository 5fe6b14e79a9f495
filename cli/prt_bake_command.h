// `lumagraph bake --mode prt` and the merge of its parts: per-vertex transfer vectors of a mesh
// or scene for gi.prt (docs/prt.md), whole or one chunk at a time. bake_command dispatches here.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"
#include "runtime/scene/load_world.h"

namespace lg::cli {

// Bakes the transfer of `input`, loaded with `load_options`, into `out`; returns the exit status.
int prt_bake_command(const Args& args, const std::string& input, const WorldLoadOptions& load_options,
                     const std::string& out);

// Merges the .lgprt parts into `out`; returns the exit status.
int prt_merge_command(const std::vector<std::string>& parts, const std::string& out);

}  // namespace lg::cli
