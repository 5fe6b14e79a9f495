#include "graph/compiler/resolve.h"

#include <bit>
#include <cstring>
#include <unordered_map>

#include "graph/short_text.h"
#include "graph/spelling.h"

namespace lg {
namespace {

template <class T>
std::string name_list(const std::vector<T>& items) {
  if (items.empty()) return "none";
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item.name;
  return out;
}

template <class T>
std::vector<std::string> names_of(const std::vector<T>& items) {
  std::vector<std::string> out;
  for (const auto& item : items) out.push_back(item.name);
  return out;
}

// Ids and type names are short: eight bytes a step, inline, where std::hash makes an
// out-of-line call and FNV-1a a multiply per byte.
struct NameHash {
  static uint64_t load(const char* p, size_t bytes) {
    uint64_t word = 0;
    std::memcpy(&word, p, bytes);
    return word;
  }
  static uint64_t mix(uint64_t h) {
    h *= 0x9e3779b97f4a7c15ull;
    return h ^ (h >> 29);
  }
  size_t operator()(std::string_view name) const {
    const char* p = name.data();
    size_t n = name.size();
    uint64_t h = n;
    for (; n >= 8; p += 8, n -= 8) h = mix(h ^ load(p, 8));
    // The last 1 to 7 bytes, read as two overlapping runs of fixed size (no variable-size copy).
    if (n >= 4)
      h = mix(h ^ (load(p, 4) | load(p + n - 4, 4) << 32));
    else if (n > 0)
      h = mix(h ^ (uint64_t{static_cast<unsigned char>(p[0])} | uint64_t{static_cast<unsigned char>(p[n / 2])} << 8 |
                   uint64_t{static_cast<unsigned char>(p[n - 1])} << 16));
    return static_cast<size_t>(h ^ (h >> 32));
  }
};

// Node index by id: open addressing in one array, as a map with a node per entry costs an
// allocation per graph node. Each slot keeps its id's hash, and the ids are read from the
// resolved graph's compact copy: a lookup compares hashes in the slots and reads one short run
// of text, instead of a graph node's id scattered through the node list (a cache miss each in
// large graphs).
class NodeIds {
 public:
  // Fills `ids` (id_text, id_starts) from the graph, and looks ids up there.
  NodeIds(const Graph& g, ResolvedGraph& ids) : ids_(ids), slots_(std::bit_ceil(2 * g.nodes.size() + 1)) {
    size_t bytes = 0;
    for (const GraphNode& n : g.nodes) bytes += n.id.size();
    ids.id_text.reserve(bytes);
    ids.id_starts.reserve(g.nodes.size() + 1);
    for (const GraphNode& n : g.nodes) {
      ids.id_starts.push_back(static_cast<uint32_t>(ids.id_text.size()));
      ids.id_text += n.id;
    }
    ids.id_starts.push_back(static_cast<uint32_t>(ids.id_text.size()));
    for (size_t k = 0; k < g.nodes.size(); ++k) {
      const size_t hash = NameHash{}(g.nodes[k].id);
      Slot& s = slots_[slot(g.nodes[k].id, hash)];
      if (s.node < 0) s = {static_cast<uint32_t>(hash), static_cast<int>(k)};  // a repeated id keeps its first
    }
  }

  int find(std::string_view id) const { return slots_[slot(id, NameHash{}(id))].node; }

 private:
  struct Slot {
    uint32_t hash = 0;  // the low bits of the id's hash
    int node = -1;      // node index, or -1 for an empty slot
  };
  const ResolvedGraph& ids_;
  CachedVector<Slot> slots_;  // never more than half full

  // The slot holding `id`, or the empty one where it would go.
  size_t slot(std::string_view id, size_t hash) const {
    const size_t mask = slots_.size() - 1;
    size_t s = hash & mask;
    while (slots_[s].node >= 0 &&
           (slots_[s].hash != static_cast<uint32_t>(hash) || !same_short_text(ids_.id(slots_[s].node), id)))
      s = (s + 1) & mask;
    return s;
  }
};

class Resolver {
 public:
  Resolver(const Graph& g, const Registry& r, Diagnostics& d) : g_(g), r_(r), d_(d) {}

  ResolvedGraph run() {
    out_.graph = &g_;
    out_.nodes.resize(g_.nodes.size());
    size_t params = 0, inputs = 0;
    // A graph uses few types many times: each is looked up in the registry once.
    std::unordered_map<std::string_view, const NodeSchema*, NameHash> schemas;
    for (size_t k = 0; k < g_.nodes.size(); ++k) {
      auto [it, added] = schemas.try_emplace(g_.nodes[k].type, nullptr);
      if (added) it->second = r_.find(g_.nodes[k].type);
      if (const NodeSchema* s = out_.nodes[k].schema = it->second) {
        params += s->params.size();
        inputs += s->inputs.size();
      }
    }
    // Sized whole, once: the nodes' spans point into them.
    out_.param_values.resize(params);
    out_.input_links.assign(inputs, -1);
    for (size_t k = 0; k < g_.nodes.size(); ++k) node(static_cast<int>(k));
    out_.links.reserve(g_.links.size());  // broken links are not kept: at most this many
    for (size_t k = 0; k < g_.links.size(); ++k) link(static_cast<int>(k));
    for (size_t k = 0; k < g_.outputs.size(); ++k) output(static_cast<int>(k));
    return std::move(out_);
  }

 private:
  const Graph& g_;
  const Registry& r_;
  Diagnostics& d_;
  ResolvedGraph out_;
  NodeIds ids_{g_, out_};  // after out_, whose id_text it fills
  // Node ids compared for "did you mean" suggestions. Each unknown reference compares against
  // every id, so without a bound a file with many nodes and many bad links took hours.
  size_t guess_budget_ = 100'000;

  // The next `count` entries of `all`, from `used` on.
  template <class T>
  static std::span<T> take(CachedVector<T>& all, size_t& used, size_t count) {
    used += count;
    return {all.data() + used - count, count};
  }
  size_t params_used_ = 0, inputs_used_ = 0;  // of out_.param_values and out_.input_links

  static std::string node_pointer(int n) { return json_pointer_append("/nodes", static_cast<size_t>(n)); }

  // Where a reference sits in the file. Its JSON pointer is spelled out only for an error.
  struct RefPlace {
    const char* list;  // "/links" or "/outputs"
    int index;
    const char* field;  // "/from", "/to" or ""
    std::string pointer() const { return json_pointer_append(list, static_cast<size_t>(index)) + field; }
  };

  void node(int n) {
    const GraphNode& gn = g_.nodes[n];
    ResolvedNode& rn = out_.nodes[n];
    if (!rn.schema) [[unlikely]] {
      unknown_type(n);
      return;
    }
    const NodeSchema& s = *rn.schema;
    rn.input_link = take(out_.input_links, inputs_used_, s.inputs.size());
    rn.params = take(out_.param_values, params_used_, s.params.size());
    for (size_t p = 0; p < s.params.size(); ++p) rn.params[p] = &s.params[p].default_value;
    for (const auto& [name, value] : gn.params.members()) {
      int index = s.find_param(name);
      if (index >= 0) [[likely]]
        rn.params[index] = &value;
      else
        no_such_param(n, name, value);
    }
  }

  // The reports are kept out of line, here and below: inlined, their strings made every call
  // of the lookups set up a large stack frame.
  [[gnu::noinline]] void unknown_type(int n) {
    const GraphNode& gn = g_.nodes[n];
    std::string message = "unknown node type '" + gn.type + "'";
    std::string guess = r_.closest_type(gn.type);
    message += guess.empty() ? "; `lumagraph nodes` lists the known types" : "; did you mean '" + guess + "'?";
    d_.error(gn.type_pos, node_pointer(n) + "/type", message);
  }

  [[gnu::noinline]] void no_such_param(int n, const std::string& name, const JsonValue& value) {
    const GraphNode& gn = g_.nodes[n];
    const NodeSchema& s = *out_.nodes[n].schema;
    std::string message = "node '" + gn.id + "' (" + s.type + ") has no param '" + name + "'";
    std::string guess = closest_name(name, names_of(s.params));
    message += guess.empty() ? "; its params are: " + name_list(s.params) : "; did you mean '" + guess + "'?";
    d_.error(value.pos(), node_pointer(n) + "/params/" + name, message);
  }

  // Finds the node of a reference, or reports it. Returns -1 when unknown or untyped.
  int find_node(const PortRef& ref, SourcePos pos, RefPlace place) {
    int found = ids_.find(ref.node);
    if (found < 0) [[unlikely]] {
      no_such_node(ref, pos, place);
      return -1;
    }
    return out_.nodes[found].schema ? found : -1;
  }

  [[gnu::noinline]] void no_such_node(const PortRef& ref, SourcePos pos, RefPlace place) {
    std::string guess;
    if (guess_budget_ >= g_.nodes.size()) {
      guess_budget_ -= g_.nodes.size();
      std::vector<std::string> ids;
      for (const auto& n : g_.nodes) ids.push_back(n.id);
      guess = closest_name(ref.node, ids);
    }
    d_.error(pos, place.pointer(),
             "no node with id '" + ref.node + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
  }

  int find_port(const PortRef& ref, int node, bool output, SourcePos pos, RefPlace place) {
    const NodeSchema& s = *out_.nodes[node].schema;
    int index = output ? s.find_output(ref.port) : s.find_input(ref.port);
    if (index >= 0) [[likely]]
      return index;
    no_such_port(ref, s, output, pos, place);
    return -1;
  }

  [[gnu::noinline]] void no_such_port(const PortRef& ref, const NodeSchema& s, bool output, SourcePos pos,
                                      RefPlace place) {
    const auto& ports = output ? s.outputs : s.inputs;
    const auto& other = output ? s.inputs : s.outputs;
    std::string message =
        "node '" + ref.node + "' (" + s.type + ") has no " + (output ? "output" : "input") + " '" + ref.port + "'";
    bool wrong_direction = false;
    for (const auto& p : other) wrong_direction |= p.name == ref.port;
    if (wrong_direction)
      message += std::string("; '") + ref.port + "' is an " + (output ? "input" : "output");
    else {
      std::string guess = closest_name(ref.port, names_of(ports));
      message += guess.empty() ? std::string("; its ") + (output ? "outputs" : "inputs") + " are: " + name_list(ports)
                               : "; did you mean '" + guess + "'?";
    }
    d_.error(pos, place.pointer(), message);
  }

  void link(int k) {
    const GraphLink& gl = g_.links[k];
    const RefPlace from{"/links", k, "/from"}, to{"/links", k, "/to"};
    ResolvedLink rl;
    rl.source = k;
    rl.from_node = find_node(gl.from, gl.from_pos, from);
    rl.to_node = find_node(gl.to, gl.to_pos, to);
    if (rl.from_node >= 0) rl.from_port = find_port(gl.from, rl.from_node, true, gl.from_pos, from);
    if (rl.to_node >= 0) rl.to_port = find_port(gl.to, rl.to_node, false, gl.to_pos, to);
    if (rl.to_port >= 0 && rl.from_port < 0 && out_.nodes[rl.to_node].input_link[rl.to_port] == -1)
      out_.nodes[rl.to_node].input_link[rl.to_port] = broken_link;
    if (rl.from_port < 0 || rl.to_port < 0) return;
    rl.history = out_.nodes[rl.to_node].schema->inputs[rl.to_port].history;
    int& slot = out_.nodes[rl.to_node].input_link[rl.to_port];
    int index = static_cast<int>(out_.links.size());
    if (slot == broken_link) slot = -1;
    if (slot >= 0) {
      const GraphLink& first = g_.links[out_.links[slot].source];
      d_.error(gl.to_pos, to.pointer(),
               "input '" + gl.to.text() + "' is already linked from '" + first.from.text() + "' (line " +
                   std::to_string(first.to_pos.line) + "); an input takes one link");
      return;
    }
    slot = index;
    out_.links.push_back(rl);
  }

  void output(int k) {
    const GraphOutput& o = g_.outputs[k];
    const RefPlace place{"/outputs", k, ""};
    int node = find_node(o.port, o.pos, place);
    if (node < 0) return;
    int port = find_port(o.port, node, true, o.pos, place);
    if (port >= 0) out_.outputs.emplace_back(node, port);
  }
};

}  // namespace

ResolvedGraph resolve(const Graph& graph, const Registry& registry, Diagnostics& diagnostics) {
  return Resolver(graph, registry, diagnostics).run();
}

JsonValue dump_resolved(const ResolvedGraph& resolved) {
  const Graph& g = *resolved.graph;
  JsonValue out = JsonValue::object();
  JsonValue& nodes = out.set("nodes", JsonValue::array());
  for (size_t n = 0; n < resolved.nodes.size(); ++n) {
    const ResolvedNode& rn = resolved.nodes[n];
    JsonValue& node = nodes.push(JsonValue::object());
    node.set("id", g.nodes[n].id);
    node.set("type", rn.schema ? rn.schema->type : "(unknown)");
    if (!rn.schema) continue;
    JsonValue& params = node.set("params", JsonValue::object());
    for (size_t p = 0; p < rn.params.size(); ++p) params.set(rn.schema->params[p].name, *rn.params[p]);
  }
  JsonValue& links = out.set("links", JsonValue::array());
  for (const auto& l : resolved.links) {
    JsonValue& link = links.push(JsonValue::object());
    link.set("from", g.nodes[l.from_node].id + "." + resolved.nodes[l.from_node].schema->outputs[l.from_port].name);
    link.set("to", g.nodes[l.to_node].id + "." + resolved.nodes[l.to_node].schema->inputs[l.to_port].name);
    if (l.history) link.set("history", true);
  }
  return out;
}

}  // namespace lg
