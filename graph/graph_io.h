// Phase 1, parse: JSON text -> Graph, and back. Structural errors (wrong format version,
// missing or misspelt keys, bad ids, malformed "node.port" references) are all reported;
// types and ports are checked later, against the registry.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "graph/diagnostics.h"
#include "graph/graph.h"
#include "graph/json_value.h"

namespace lg {

std::optional<Graph> parse_graph(const JsonValue& root, Diagnostics& diagnostics);
std::optional<Graph> parse_graph_text(std::string_view text, Diagnostics& diagnostics);
// Reads and parses a file; diagnostics.file() is set to `path`.
std::optional<Graph> load_graph_file(const std::string& path, Diagnostics& diagnostics);

JsonValue graph_to_json(const Graph& graph);
std::string graph_to_text(const Graph& graph);
bool save_graph_file(const Graph& graph, const std::string& path, std::string* error);

// Node ids and port names: 1 to limits::max_id_length characters of [A-Za-z0-9_-].
bool is_valid_id(std::string_view id);

}  // namespace lg
