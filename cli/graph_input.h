// What compile, validate and render share: loading the graph named on the command line (or the
// embedded default graph when none is named) and the options that shape compilation.
#pragma once

#include <optional>
#include <string>

#include "cli/args.h"
#include "graph/compiler.h"
#include "graph/diagnostics.h"
#include "graph/graph.h"

namespace lg::cli {

// The options compile and validate accept, for ArgSpec.
ArgSpec graph_arg_spec();

// Loads the graph (positional argument, or the embedded default). nullopt: errors are in
// `diagnostics`.
std::optional<Graph> load_graph_argument(const Args& args, Diagnostics& diagnostics);
// The same, printing the errors (sorted by position) to stderr when there is no graph.
std::optional<Graph> load_graph_argument_or_print(const Args& args);

// Reads --size WxH into `frame` (unchanged without it); returns an error message for bad values.
std::optional<std::string> read_frame_size(const Args& args, FrameSize& frame);

// Fills scene, frame size, asset roots and aliasing from the arguments. Returns an error
// message for bad values; scene file errors go to `diagnostics`.
std::optional<std::string> read_compile_options(const Args& args, CompileOptions& options, Diagnostics& diagnostics);

}  // namespace lg::cli
