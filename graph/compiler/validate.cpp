#include "graph/compiler/validate.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace lg {
namespace {

// Shortest round form: integral limits print whole (1048576, not 1.04858e+06).
std::string format_number(double v, int digits = 15) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string range_text(const ParamSpec& spec) {
  if (spec.min && spec.max) return " from " + format_number(*spec.min) + " to " + format_number(*spec.max);
  if (spec.min) return " of at least " + format_number(*spec.min);
  if (spec.max) return " of at most " + format_number(*spec.max);
  return "";
}

bool in_range(const ParamSpec& spec, double v) {
  return (!spec.min || v >= *spec.min) && (!spec.max || v <= *spec.max);
}

// A value matches a choice to 1e-4 relative, so that 0.33333 is the 1/3 a schema lists.
bool among_choices(const ParamSpec& spec, double v) {
  return spec.choices.empty() || std::any_of(spec.choices.begin(), spec.choices.end(),
                                             [v](double c) { return std::abs(v - c) <= 1e-4 * std::abs(c); });
}

std::string choices_text(const ParamSpec& spec) {
  std::string list;
  for (double c : spec.choices) list += (list.empty() ? "" : ", ") + format_number(c, 6);
  return " among " + list;
}

std::string node_pointer(int n) {
  return json_pointer_append("/nodes", static_cast<size_t>(n));
}

// The first 8 bytes of an id as a big-endian number, zero-padded: ordering these orders the ids,
// except where they are equal and the rest of the ids decides.
uint64_t id_prefix(std::string_view id) {
  uint64_t key = 0;
  const size_t bytes = std::min<size_t>(id.size(), 8);
  for (size_t k = 0; k < bytes; ++k) key |= uint64_t{static_cast<unsigned char>(id[k])} << (56 - 8 * k);
  return key;
}

}  // namespace

std::string check_param_value(const ParamSpec& spec, const JsonValue& v) {
  bool integral = spec.type == ParamType::int_ || spec.type == ParamType::int2;
  switch (spec.type) {
    case ParamType::float_:
    case ParamType::int_:
      if (!v.is_number() || (integral && !v.is_integer()) || !in_range(spec, v.as_number()))
        return std::string(integral ? "an integer" : "a number") + range_text(spec);
      if (!among_choices(spec, v.as_number()))
        return std::string(integral ? "an integer" : "a number") + choices_text(spec);
      return {};
    case ParamType::bool_:
      return v.is_bool() ? "" : "true or false";
    case ParamType::enum_: {
      if (v.is_string() && std::find(spec.values.begin(), spec.values.end(), v.as_string()) != spec.values.end())
        return {};
      std::string list;
      for (const auto& e : spec.values) list += (list.empty() ? "" : ", ") + ("\"" + e + "\"");
      return "one of " + list;
    }
    case ParamType::string:
    case ParamType::path:
      return v.is_string() ? "" : "a string";
    case ParamType::float2:
    case ParamType::float3:
    case ParamType::float4:
    case ParamType::int2: {
      size_t n = param_components(spec.type);
      bool ok = v.is_array() && v.items().size() == n;
      for (size_t k = 0; ok && k < n; ++k) {
        const JsonValue& c = v.items()[k];
        ok = c.is_number() && (!integral || c.is_integer()) && in_range(spec, c.as_number());
      }
      if (ok) return {};
      return "an array of " + std::to_string(n) + (integral ? " integers" : " numbers") + range_text(spec);
    }
  }
  return "a valid value";
}

namespace {

// Params a schema orders ("less_than"): where the graph sets either, the two values (each valid,
// or its own error said so) must be in order. The error lands on a value the graph wrote.
void check_param_order(const NodeSchema& s, const GraphNode& gn, int n, Diagnostics& diagnostics) {
  for (const ParamSpec& spec : s.params) {
    if (spec.less_than < 0) continue;
    const ParamSpec& other = s.params[size_t(spec.less_than)];
    const JsonValue* mine = gn.params.find(spec.name);
    const JsonValue* theirs = gn.params.find(other.name);
    if (!mine && !theirs) continue;  // the defaults are in order: the schema reader checks
    const JsonValue& a = mine ? *mine : spec.default_value;
    const JsonValue& b = theirs ? *theirs : other.default_value;
    if (!check_param_value(spec, a).empty() || !check_param_value(other, b).empty()) continue;
    if (a.as_number() < b.as_number()) continue;
    auto value = [](const ParamSpec& p, const JsonValue& v, bool written) {
      return p.name + " " + format_number(v.as_number()) + (written ? "" : " (its default)");
    };
    diagnostics.error((mine ? mine : theirs)->pos(), node_pointer(n) + "/params/" + (mine ? spec.name : other.name),
                      "param '" + spec.name + "' of node '" + gn.id + "' (" + s.type + ") must be below its param '" +
                          other.name + "': " + value(spec, a, mine) + " is not below " + value(other, b, theirs));
  }
}

}  // namespace

std::optional<CachedVector<int>> validate(const ResolvedGraph& resolved, const AssetRoots& roots,
                                          Diagnostics& diagnostics) {
  const Graph& g = *resolved.graph;
  size_t before = diagnostics.error_count();
  const int node_count = static_cast<int>(resolved.nodes.size());
  bool has_root = !resolved.outputs.empty();

  for (int n = 0; n < node_count; ++n) {
    const ResolvedNode& rn = resolved.nodes[n];
    if (!rn.schema) continue;
    const NodeSchema& s = *rn.schema;
    const GraphNode& gn = g.nodes[n];
    has_root |= s.is_output;
    for (size_t p = 0; p < s.params.size(); ++p) {
      const ParamSpec& spec = s.params[p];
      const JsonValue* written = gn.params.find(spec.name);
      if (!written) {
        // Defaults are valid by construction (tests check every schema), but a default path
        // names a file that may not be there: check it like a written one.
        std::string why;
        if (spec.type == ParamType::path &&
            !resolve_asset_path(g.file, spec.default_value.as_string(), roots, spec.extensions, &why))
          diagnostics.error(
              gn.pos, node_pointer(n),
              "param '" + spec.name + "' of node '" + gn.id + "' is not set, so its default is used: " + why);
        continue;
      }
      auto pointer = [&] { return node_pointer(n) + "/params/" + spec.name; };
      std::string expected = check_param_value(spec, *written);
      if (!expected.empty()) {
        diagnostics.error(written->pos(), pointer(),
                          "param '" + spec.name + "' of node '" + gn.id + "' (" + s.type + ") must be " + expected +
                              (spec.unit.empty() ? "" : " (" + spec.unit + ")"));
      } else if (spec.type == ParamType::path) {
        std::string why;
        if (!resolve_asset_path(g.file, written->as_string(), roots, spec.extensions, &why))
          diagnostics.error(written->pos(), pointer(), "param '" + spec.name + "' of node '" + gn.id + "': " + why);
      }
    }
    check_param_order(s, gn, n, diagnostics);
    for (size_t i = 0; i < s.inputs.size(); ++i)
      if (!s.inputs[i].optional && rn.input_link[i] == -1)
        diagnostics.error(gn.pos, node_pointer(n),
                          "node '" + gn.id + "' (" + s.type + ") needs its input '" + s.inputs[i].name + "' (" +
                              s.inputs[i].type.name() + ") linked");
  }

  for (const auto& l : resolved.links) {
    const PortSpec& from = resolved.nodes[l.from_node].schema->outputs[l.from_port];
    const PortSpec& to = resolved.nodes[l.to_node].schema->inputs[l.to_port];
    std::string why;
    if (!port_types_compatible(from.type, to.type, &why)) {
      const GraphLink& gl = g.links[l.source];
      diagnostics.error(gl.to_pos, json_pointer_append("/links", static_cast<size_t>(l.source)) + "/to",
                        "cannot link " + gl.from.text() + " (" + from.type.name() + ") to " + gl.to.text() + " (" +
                            to.type.name() + "): " + why);
    }
  }

  // Not when a node type or a listed output did not resolve (already reported): the unknown
  // type or the misspelt output may be what the graph asks for.
  bool unresolved = resolved.outputs.size() < g.outputs.size();
  for (const ResolvedNode& rn : resolved.nodes) unresolved |= !rn.schema;
  if (!has_root && !unresolved && diagnostics.error_count() == before)
    diagnostics.error({1, 1}, "/outputs",
                      "the graph asks for nothing: list ports under \"outputs\" or add an output node");

  // Kahn's algorithm over non-history links, ties broken by id so file order does not matter.
  // Each node's consumers, all in one array: node n's are consumers[start[n] .. start[n + 1]).
  CachedVector<int> start(node_count + 1, 0), pending(node_count, 0);
  for (const auto& l : resolved.links)
    if (!l.history) ++start[l.from_node + 1], ++pending[l.to_node];
  for (int n = 0; n < node_count; ++n) start[n + 1] += start[n];
  CachedVector<int> consumers(start[node_count]), fill(start.begin(), start.end() - 1);
  for (const auto& l : resolved.links)
    if (!l.history) consumers[fill[l.from_node]++] = l.to_node;
  CachedVector<uint64_t> prefix(node_count);
  for (int n = 0; n < node_count; ++n) prefix[n] = id_prefix(g.nodes[n].id);
  auto later = [&](int a, int b) {
    return prefix[a] != prefix[b] ? prefix[a] > prefix[b] : g.nodes[a].id > g.nodes[b].id;
  };
  CachedVector<int> heap;
  heap.reserve(node_count);
  std::priority_queue<int, CachedVector<int>, decltype(later)> ready(later, std::move(heap));
  for (int n = 0; n < node_count; ++n)
    if (pending[n] == 0) ready.push(n);
  CachedVector<int> order;
  order.reserve(node_count);
  while (!ready.empty()) {
    int n = ready.top();
    ready.pop();
    order.push_back(n);
    for (int k = start[n]; k < start[n + 1]; ++k)
      if (--pending[consumers[k]] == 0) ready.push(consumers[k]);
  }
  if (static_cast<int>(order.size()) < node_count) {
    // Walk back along unfinished inputs from an unfinished node until a node repeats: a cycle.
    int start = -1;
    for (int n = 0; n < node_count && start < 0; ++n)
      if (pending[n] > 0) start = n;
    std::vector<int> seen(node_count, -1), path;
    int n = start, via_link = -1;
    while (seen[n] < 0) {
      seen[n] = static_cast<int>(path.size());
      path.push_back(n);
      for (int li : resolved.nodes[n].input_link) {
        if (li < 0 || resolved.links[li].history || pending[resolved.links[li].from_node] == 0) continue;
        via_link = li;
        n = resolved.links[li].from_node;
        break;
      }
    }
    std::vector<int> cycle(path.begin() + seen[n], path.end());
    std::reverse(cycle.begin(), cycle.end());
    std::string text;
    for (int c : cycle) text += g.nodes[c].id + " -> ";
    text += g.nodes[cycle.front()].id;
    const GraphLink& gl = g.links[resolved.links[via_link].source];
    diagnostics.error(gl.to_pos,
                      json_pointer_append("/links", static_cast<size_t>(resolved.links[via_link].source)) + "/to",
                      "cycle: " + text + "; a loop is only allowed through a history input");
  }
  if (diagnostics.error_count() > before) return std::nullopt;
  return order;
}

JsonValue dump_node_order(const ResolvedGraph& resolved, const CachedVector<int>& order) {
  JsonValue out = JsonValue::array();
  for (int n : order) out.push(resolved.graph->nodes[n].id);
  return out;
}

}  // namespace lg
