// Reads a node schema from its JSON text (nodes/<category>/<name>/schema.json). Mistakes in a
// schema are reported like mistakes in a graph: file, line, column and JSON pointer.
#pragma once

#include <optional>
#include <string_view>

#include "graph/diagnostics.h"
#include "graph/schema.h"

namespace lg {

std::optional<NodeSchema> read_node_schema(std::string_view json_text, Diagnostics& diagnostics);

}  // namespace lg
