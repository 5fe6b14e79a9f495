#include "editor/graph_edits.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lg::editor {

GraphNode* find_node(Graph& graph, std::string_view id) {
  auto it = std::find_if(graph.nodes.begin(), graph.nodes.end(), [&](const GraphNode& n) { return n.id == id; });
  return it == graph.nodes.end() ? nullptr : &*it;
}

const GraphNode* find_node(const Graph& graph, std::string_view id) {
  return find_node(const_cast<Graph&>(graph), id);
}

std::string unique_id_like(const Graph& graph, std::string_view id) {
  std::string base(id.substr(0, id.find_last_not_of("0123456789") + 1));
  if (base.empty()) base = "node";
  std::string fresh = base;
  for (int n = 2; find_node(graph, fresh); ++n) fresh = base + std::to_string(n);
  return fresh;
}

std::string unique_node_id(const Graph& graph, std::string_view type) {
  return unique_id_like(graph, type.substr(type.rfind('.') == std::string_view::npos ? 0 : type.rfind('.') + 1));
}

static JsonValue& positions_of(Graph& graph) {
  if (!graph.editor.is_object()) graph.editor = JsonValue::object();
  if (const JsonValue* p = graph.editor.find("positions"); p && p->is_object()) return const_cast<JsonValue&>(*p);
  return graph.editor.set("positions", JsonValue::object());
}

static void erase_member(JsonValue& object, std::string_view key) {
  auto& m = object.members();
  m.erase(std::remove_if(m.begin(), m.end(), [&](const JsonValue::Member& e) { return e.first == key; }), m.end());
}

std::optional<Position> node_position(const Graph& graph, std::string_view id) {
  const JsonValue* positions = graph.editor.find("positions");
  const JsonValue* p = positions ? positions->find(id) : nullptr;
  if (!p || !p->is_array() || p->size() != 2 || !p->items()[0].is_number() || !p->items()[1].is_number())
    return std::nullopt;
  return Position{p->items()[0].as_number(), p->items()[1].as_number()};
}

void set_node_position(Graph& graph, const std::string& id, Position p) {
  JsonValue xy = JsonValue::array();
  // Whole pixels: positions are for people, and integers keep the files tidy.
  xy.push(JsonValue(std::round(p[0])));
  xy.push(JsonValue(std::round(p[1])));
  positions_of(graph).set(id, std::move(xy));
}

std::string add_node(Graph& graph, std::string_view type, Position p) {
  GraphNode node;
  node.id = unique_node_id(graph, type);
  node.type = std::string(type);
  graph.nodes.push_back(node);
  set_node_position(graph, node.id, p);
  return node.id;
}

void remove_nodes(Graph& graph, const std::set<std::string>& ids) {
  auto gone = [&](const std::string& id) { return ids.count(id) > 0; };
  std::erase_if(graph.nodes, [&](const GraphNode& n) { return gone(n.id); });
  std::erase_if(graph.links, [&](const GraphLink& l) { return gone(l.from.node) || gone(l.to.node); });
  std::erase_if(graph.outputs, [&](const GraphOutput& o) { return gone(o.port.node); });
  if (const JsonValue* positions = graph.editor.find("positions"); positions && positions->is_object())
    for (const std::string& id : ids) erase_member(positions_of(graph), id);
}

static bool same(const PortRef& a, const PortRef& b) {
  return a.node == b.node && a.port == b.port;
}

bool has_link(const Graph& graph, const PortRef& from, const PortRef& to) {
  return std::any_of(graph.links.begin(), graph.links.end(),
                     [&](const GraphLink& l) { return same(l.from, from) && same(l.to, to); });
}

void add_link(Graph& graph, const PortRef& from, const PortRef& to) {
  if (has_link(graph, from, to)) return;
  GraphLink link;
  link.from = from;
  link.to = to;
  graph.links.push_back(link);
}

void remove_link(Graph& graph, const PortRef& from, const PortRef& to) {
  std::erase_if(graph.links, [&](const GraphLink& l) { return same(l.from, from) && same(l.to, to); });
}

void set_param(Graph& graph, std::string_view node, const std::string& name, const JsonValue& value) {
  GraphNode* n = find_node(graph, node);
  if (!n) return;
  if (!n->params.is_object()) n->params = JsonValue::object();
  if (value.is_null())
    erase_member(n->params, name);
  else
    n->params.set(name, value);
}

void apply_preset(Graph& graph, std::string_view node, const NodeSchema& schema, const ParamPreset& preset) {
  for (const auto& [param, value] : preset.values) set_param(graph, node, schema.params[param].name, value);
}

int matching_preset(const GraphNode& node, const NodeSchema& schema) {
  for (size_t k = 0; k < schema.presets.size(); ++k) {
    const bool all = std::all_of(schema.presets[k].values.begin(), schema.presets[k].values.end(), [&](const auto& v) {
      const ParamSpec& spec = schema.params[v.first];
      const JsonValue* set = node.params.find(spec.name);
      return (set ? *set : spec.default_value) == v.second;
    });
    if (all) return int(k);
  }
  return -1;
}

Graph extract_nodes(const Graph& graph, const std::set<std::string>& ids) {
  Graph part;
  part.name = graph.name;
  for (const GraphNode& n : graph.nodes)
    if (ids.count(n.id)) {
      part.nodes.push_back(n);
      if (auto p = node_position(graph, n.id)) set_node_position(part, n.id, *p);
    }
  for (const GraphLink& l : graph.links)
    if (ids.count(l.from.node) && ids.count(l.to.node)) part.links.push_back(l);
  return part;
}

std::vector<std::string> paste_nodes(Graph& graph, const Graph& fragment, Position offset) {
  std::map<std::string, std::string> renamed;
  std::vector<std::string> added;
  for (const GraphNode& n : fragment.nodes) {
    GraphNode copy = n;
    copy.id = unique_id_like(graph, n.id);
    renamed[n.id] = copy.id;
    graph.nodes.push_back(copy);
    Position p = node_position(fragment, n.id).value_or(Position{0, 0});
    set_node_position(graph, copy.id, {p[0] + offset[0], p[1] + offset[1]});
    added.push_back(copy.id);
  }
  for (const GraphLink& l : fragment.links) {
    auto from = renamed.find(l.from.node), to = renamed.find(l.to.node);
    if (from != renamed.end() && to != renamed.end())
      add_link(graph, {from->second, l.from.port}, {to->second, l.to.port});
  }
  return added;
}

}  // namespace lg::editor
