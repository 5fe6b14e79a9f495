// Edits of a Graph as pure functions: adding and removing nodes and links, moving nodes, setting
// params, copying a selection out and pasting it back with fresh ids. The editor's undo commands
// are snapshots of their results, so these are the only places that change a graph's content.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"
#include "graph/schema.h"

namespace lg::editor {

using Position = std::array<double, 2>;

GraphNode* find_node(Graph& graph, std::string_view id);
const GraphNode* find_node(const Graph& graph, std::string_view id);

// An id not used in `graph`, from the last part of the type: "bloom", then "bloom2", "bloom3"...
std::string unique_node_id(const Graph& graph, std::string_view type);
// An id not used in `graph` like `id`: "sky" or "sky4" give "sky2" when "sky" is taken.
std::string unique_id_like(const Graph& graph, std::string_view id);

// Positions live under editor.positions as {"id": [x, y]}, as the runtime's loader ignores them.
std::optional<Position> node_position(const Graph& graph, std::string_view id);
void set_node_position(Graph& graph, const std::string& id, Position p);

// Returns the new node's id.
std::string add_node(Graph& graph, std::string_view type, Position p);
// Removes the nodes with their links, requested outputs and positions.
void remove_nodes(Graph& graph, const std::set<std::string>& ids);

bool has_link(const Graph& graph, const PortRef& from, const PortRef& to);
void add_link(Graph& graph, const PortRef& from, const PortRef& to);
void remove_link(Graph& graph, const PortRef& from, const PortRef& to);

// Sets a param as written in the file; a null value removes it (the schema default applies).
void set_param(Graph& graph, std::string_view node, const std::string& name, const JsonValue& value);

// Sets every param of `preset` (one of the node's schema's) on the node.
void apply_preset(Graph& graph, std::string_view node, const NodeSchema& schema, const ParamPreset& preset);
// The index in schema.presets of the first preset whose values the node holds (set in the file or
// by default), or -1: the node's params are not any preset's.
int matching_preset(const GraphNode& node, const NodeSchema& schema);

// The nodes `ids`, the links between them and their positions, as a graph of its own.
Graph extract_nodes(const Graph& graph, const std::set<std::string>& ids);
// Adds the nodes of `fragment` with fresh ids, links among them and positions moved by `offset`;
// returns the new ids.
std::vector<std::string> paste_nodes(Graph& graph, const Graph& fragment, Position offset);

}  // namespace lg::editor
