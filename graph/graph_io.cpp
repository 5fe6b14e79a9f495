#include "graph/graph_io.h"

#include <algorithm>
#include <unordered_map>

#include "graph/json_reader.h"
#include "graph/json_writer.h"
#include "graph/limits.h"
#include "graph/spelling.h"

namespace lg {
namespace {

class GraphParser {
 public:
  GraphParser(Graph& g, Diagnostics& d) : g_(g), d_(d) {}

  void parse(const JsonValue& root) {
    if (!root.is_object()) {
      d_.error(root.pos(), "", std::string("expected a graph object {\"format\": \"") + graph_format +
                                   "\", ...}, found " + JsonValue::kind_name(root.kind()));
      return;
    }
    for (const auto& [key, value] : root.members()) {
      std::string p = json_pointer_append("", key);
      if (key == "format") format(value, p);
      else if (key == "name") g_.name = string_value(value, p);
      else if (key == "nodes") list(value, p, limits::max_nodes, "nodes", [&](const JsonValue& v, const std::string& ip) { node(v, ip); });
      else if (key == "links") list(value, p, limits::max_array_items, "links", [&](const JsonValue& v, const std::string& ip) { link(v, ip); });
      else if (key == "outputs") list(value, p, limits::max_nodes, "outputs", [&](const JsonValue& v, const std::string& ip) { output(v, ip); });
      else if (key == "editor") editor(value, p);
      else unknown_key(key, value, p, {"format", "name", "nodes", "links", "outputs", "editor"});
    }
    if (!root.find("format"))
      d_.error(root.pos(), "", std::string("missing \"format\": \"") + graph_format + "\"");
    if (!root.find("nodes")) d_.error(root.pos(), "", "missing \"nodes\": [...]");
  }

 private:
  Graph& g_;
  Diagnostics& d_;
  std::unordered_map<std::string, SourcePos> ids_;

  void unknown_key(const std::string& key, const JsonValue& v, const std::string& p,
                   const std::vector<std::string>& known) {
    std::string message = "unknown key '" + key + "'";
    std::string guess = closest_name(key, known);
    if (!guess.empty()) message += "; did you mean '" + guess + "'?";
    else {
      message += "; expected";
      for (size_t k = 0; k < known.size(); ++k) message += (k ? ", " : " ") + known[k];
    }
    d_.error(v.pos(), p, message);
  }

  void format(const JsonValue& v, const std::string& p) {
    if (!v.is_string()) {
      d_.error(v.pos(), p, std::string("expected the string \"") + graph_format + "\"");
    } else if (v.as_string() != graph_format) {
      std::string message = "unsupported format '" + v.as_string() + "'; this build reads " + graph_format;
      if (v.as_string().rfind("lumagraph/", 0) == 0) message += " (the file may come from a newer version)";
      d_.error(v.pos(), p, message);
    }
  }

  std::string string_value(const JsonValue& v, const std::string& p) {
    if (v.is_string()) return v.as_string();
    d_.error(v.pos(), p, std::string("expected a string, found ") + JsonValue::kind_name(v.kind()));
    return {};
  }

  template <class F>
  void list(const JsonValue& v, const std::string& p, size_t limit, const char* what, F&& each) {
    if (!v.is_array()) {
      d_.error(v.pos(), p, std::string("expected an array, found ") + JsonValue::kind_name(v.kind()));
      return;
    }
    if (v.items().size() > limit) {
      d_.error(v.pos(), p, "too many " + std::string(what) + ": " + std::to_string(v.items().size()) +
                               " (the limit is " + std::to_string(limit) + ")");
      return;
    }
    for (size_t k = 0; k < v.items().size(); ++k) each(v.items()[k], json_pointer_append(p, k));
  }

  void node(const JsonValue& v, const std::string& p) {
    if (!v.is_object()) {
      d_.error(v.pos(), p, std::string("expected a node object {\"id\": ..., \"type\": ...}, found ") +
                               JsonValue::kind_name(v.kind()));
      return;
    }
    GraphNode n;
    n.pos = v.pos();
    for (const auto& [key, value] : v.members()) {
      std::string kp = json_pointer_append(p, key);
      if (key == "id") {
        n.id = string_value(value, kp);
        if (value.is_string() && !is_valid_id(n.id)) {
          // A long id is only wrong by its length: say so rather than make the reader count.
          bool only_length = std::all_of(n.id.begin(), n.id.end(), [](const char& c) { return is_valid_id({&c, 1}); });
          std::string what = only_length ? "invalid node id: it has " + std::to_string(n.id.size()) + " characters; "
                                         : "invalid node id '" + n.id + "': ";
          d_.error(value.pos(), kp, what + "use 1 to " + std::to_string(limits::max_id_length) +
                                        " letters, digits, '_' or '-'");
          n.id.clear();
        }
      } else if (key == "type") {
        n.type = string_value(value, kp);
        n.type_pos = value.pos();
      } else if (key == "params") {
        if (value.is_object()) n.params = value;
        else d_.error(value.pos(), kp, std::string("expected an object of params, found ") + JsonValue::kind_name(value.kind()));
      } else {
        unknown_key(key, value, kp, {"id", "type", "params"});
      }
    }
    if (!v.find("id")) d_.error(v.pos(), p, "node has no \"id\"");
    if (!v.find("type")) d_.error(v.pos(), p, "node has no \"type\"");
    if (!n.id.empty()) {
      auto [it, fresh] = ids_.emplace(n.id, v.find("id")->pos());
      if (!fresh) {
        d_.error(v.find("id")->pos(), json_pointer_append(p, "id"),
                 "duplicate node id '" + n.id + "' (first used at line " + std::to_string(it->second.line) +
                     ", column " + std::to_string(it->second.column) + ")");
        return;
      }
    }
    g_.nodes.push_back(std::move(n));
  }

  bool port_ref(const JsonValue& v, const std::string& p, PortRef& out) {
    if (!v.is_string()) {
      d_.error(v.pos(), p, std::string("expected \"node.port\", found ") + JsonValue::kind_name(v.kind()));
      return false;
    }
    const std::string& s = v.as_string();
    size_t dot = s.find('.');
    if (dot == std::string::npos || s.find('.', dot + 1) != std::string::npos ||
        !is_valid_id(s.substr(0, dot)) || !is_valid_id(s.substr(dot + 1))) {
      d_.error(v.pos(), p, "expected \"node.port\" (for example \"sky.cube\"), found \"" + s + "\"");
      return false;
    }
    out = {s.substr(0, dot), s.substr(dot + 1)};
    return true;
  }

  void link(const JsonValue& v, const std::string& p) {
    if (!v.is_object()) {
      d_.error(v.pos(), p, std::string("expected a link {\"from\": \"node.port\", \"to\": \"node.port\"}, found ") +
                               JsonValue::kind_name(v.kind()));
      return;
    }
    GraphLink l;
    bool ok = true;
    for (const auto& [key, value] : v.members()) {
      std::string kp = json_pointer_append(p, key);
      if (key == "from") ok &= port_ref(value, kp, l.from), l.from_pos = value.pos();
      else if (key == "to") ok &= port_ref(value, kp, l.to), l.to_pos = value.pos();
      else unknown_key(key, value, kp, {"from", "to"}), ok = false;
    }
    for (const char* key : {"from", "to"})
      if (!v.find(key)) d_.error(v.pos(), p, std::string("link has no \"") + key + "\""), ok = false;
    if (ok) g_.links.push_back(std::move(l));
  }

  void output(const JsonValue& v, const std::string& p) {
    GraphOutput o;
    o.pos = v.pos();
    if (port_ref(v, p, o.port)) g_.outputs.push_back(std::move(o));
  }

  void editor(const JsonValue& v, const std::string& p) {
    if (v.is_object()) g_.editor = v;
    else d_.error(v.pos(), p, std::string("expected an object, found ") + JsonValue::kind_name(v.kind()));
  }
};

}  // namespace

bool is_valid_id(std::string_view id) {
  if (id.empty() || id.size() > limits::max_id_length) return false;
  for (char c : id)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-'))
      return false;
  return true;
}

std::optional<Graph> parse_graph(const JsonValue& root, Diagnostics& diagnostics) {
  size_t before = diagnostics.error_count();
  Graph graph;
  graph.file = diagnostics.file();
  GraphParser(graph, diagnostics).parse(root);
  if (diagnostics.error_count() > before) return std::nullopt;
  return graph;
}

std::optional<Graph> parse_graph_text(std::string_view text, Diagnostics& diagnostics) {
  auto root = read_json(text, diagnostics);
  if (!root) return std::nullopt;
  return parse_graph(*root, diagnostics);
}

std::optional<Graph> load_graph_file(const std::string& path, Diagnostics& diagnostics) {
  diagnostics.set_file(path);
  auto root = read_json_file(path, diagnostics);
  if (!root) return std::nullopt;
  return parse_graph(*root, diagnostics);
}

JsonValue graph_to_json(const Graph& graph) {
  JsonValue root = JsonValue::object();
  root.set("format", graph_format);
  if (!graph.name.empty()) root.set("name", graph.name);
  JsonValue& nodes = root.set("nodes", JsonValue::array());
  for (const auto& n : graph.nodes) {
    JsonValue& node = nodes.push(JsonValue::object());
    node.set("id", n.id);
    node.set("type", n.type);
    if (!n.params.members().empty()) node.set("params", n.params);
  }
  JsonValue& links = root.set("links", JsonValue::array());
  for (const auto& l : graph.links) {
    JsonValue& link = links.push(JsonValue::object());
    link.set("from", l.from.text());
    link.set("to", l.to.text());
  }
  JsonValue& outputs = root.set("outputs", JsonValue::array());
  for (const auto& o : graph.outputs) outputs.push(o.port.text());
  if (!graph.editor.members().empty()) root.set("editor", graph.editor);
  return root;
}

std::string graph_to_text(const Graph& graph) { return write_json(graph_to_json(graph)); }

bool save_graph_file(const Graph& graph, const std::string& path, std::string* error) {
  return write_file_atomically(path, graph_to_text(graph), error);
}

}  // namespace lg
