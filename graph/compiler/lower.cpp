#include "graph/compiler/lower.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <initializer_list>
#include <tuple>

#include "graph/compiler/cull.h"
#include "graph/fnv1a.h"
#include "graph/json_writer.h"
#include "graph/limits.h"

namespace lg {
namespace {

// A size in texels: x rounded down, at least 1 (NaN too). Past uint32's range it is uint32's
// largest, which the extent limit then reports. No call to floor, which x86-64's baseline
// instructions cannot do in line.
uint32_t texels(double x) {
  if (!(x >= 1.0)) return 1;
  return x >= 4294967295.0 ? UINT32_MAX : static_cast<uint32_t>(x);
}

uint32_t full_mip_count(uint32_t w, uint32_t h) {
  return std::max(1u, static_cast<uint32_t>(std::bit_width(std::max(w, h))));
}

// "a/b" or "a.b.c": one string, sized once, without temporaries.
std::string joined(std::initializer_list<std::string_view> parts) {
  size_t size = 0;
  for (std::string_view p : parts) size += p.size();
  std::string out(size, '\0');
  char* at = out.data();
  for (std::string_view p : parts) at = std::copy(p.begin(), p.end(), at);
  return out;
}

// The resources of one port: a bundle's components are created together, so they are
// contiguous in LoweredGraph::resources.
struct Span {
  int first = -1, count = 0;
  bool empty() const { return count == 0; }
  int operator[](int c) const { return first + c; }
};

class Lowerer {
 public:
  Lowerer(const ResolvedGraph& r, const NodeStates& s, FrameSize f, const AssetRoots& roots, bool keep_optional,
          Diagnostics& d)
      : r_(r), s_(s), frame_(f), roots_(roots), keep_optional_(keep_optional), d_(d) {}

  LoweredGraph run(const CachedVector<int>& order) {
    const size_t count = r_.nodes.size();
    out_.nodes.resize(count);
    port_base_.resize(count + 1, 0);
    for (size_t n = 0; n < count; ++n)
      port_base_[n + 1] = port_base_[n] + static_cast<int>(r_.nodes[n].schema->outputs.size());
    ports_.resize(port_base_[count]);
    previous_.resize(port_base_[count]);
    mark_wanted_outputs();
    // Read once in file order: the loops below visit nodes in topological order, which large
    // graphs scatter, and need only this byte of each node's state.
    kinds_.resize(count);
    for (size_t n = 0; n < count; ++n) kinds_[n] = s_[n].kind;
    reserve();
    CachedVector<int> output_nodes;  // active output nodes, in order
    for (int n : order) {
      if (kinds_[n] == NodeState::Kind::culled) continue;
      if (kinds_[n] == NodeState::Kind::bypassed) {
        forward(n);
        continue;
      }
      lower_node(n);
      if (r_.nodes[n].schema->is_output) output_nodes.push_back(n);
    }
    // Room for the previous-frame copies (a source read by several history links counts once
    // per link), then backwards: binding a bundle inserts accesses, which would move the later slots.
    size_t copies = 0;
    for (auto [pass, access, link] : deferred_history_) copies += source_of(link).count;
    out_.resources.reserve(out_.resources.size() + copies);
    for (auto it = deferred_history_.rbegin(); it != deferred_history_.rend(); ++it) {
      auto [pass, access, link] = *it;
      bind_history(pass, access, link);
    }
    for (size_t k = 0; k < r_.outputs.size(); ++k) {
      auto [node, output] = r_.outputs[k];
      if (port(node, output).empty())
        d_.error(r_.graph->outputs[k].pos, json_pointer_append("/outputs", k),
                 "output '" + r_.graph->outputs[k].port.text() + "' is empty: '" + std::string(id(node)) +
                     "' is bypassed (" + s_[node].reason + ") and forwards an input that is not linked");
      export_resources(port(node, output));
      add_output(-1, r_.graph->outputs[k].port.text(), port(node, output));
    }
    for (int n : output_nodes)
      for (int li : r_.nodes[n].input_link)
        if (li >= 0) {
          export_resources(source_of(li));
          const ResolvedLink& l = r_.links[li];
          add_output(n, joined({id(l.from_node), ".", r_.nodes[l.from_node].schema->outputs[l.from_port].name}),
                     source_of(li));
        }
    return std::move(out_);
  }

 private:
  const ResolvedGraph& r_;
  const NodeStates& s_;
  FrameSize frame_;
  const AssetRoots& roots_;
  const bool keep_optional_;  // every optional output written, linked or not (a dump)
  Diagnostics& d_;
  LoweredGraph out_;
  CachedVector<char> wanted_;            // per output port: linked or listed in the file's outputs
  CachedVector<int> port_base_;          // node -> index of its first output in ports_
  CachedVector<Span> ports_;             // per output port: its resources (a bypassed node's are its input's)
  CachedVector<Span> previous_;          // per output port: previous-frame copies, made on demand
  CachedVector<Span> internal_;          // the node being lowered: its internal resources
  CachedVector<NodeState::Kind> kinds_;  // per node, a copy of its state's kind
  CachedVector<std::tuple<int, size_t, int>> deferred_history_;  // (pass, access slot, link)

  // Room for what the active nodes make (previous-frame copies aside): growing the arrays
  // instead copies them and touches twice the memory. The accesses get one block of the arena.
  void reserve() {
    size_t passes = 0, resources = 0, uses = 0;
    for (size_t n = 0; n < kinds_.size(); ++n) {
      if (kinds_[n] != NodeState::Kind::active) continue;
      const NodeSchema& s = *r_.nodes[n].schema;
      passes += s.passes.size();
      for (const auto& pass : s.passes) uses += most_accesses(s, pass);
      for (const auto& port : s.outputs) resources += port.type.components().size();
      for (const auto& port : s.resources) resources += port.type.components().size();
    }
    out_.passes.reserve(passes);
    out_.resources.reserve(resources);
    out_.arena =
        std::make_shared<std::pmr::monotonic_buffer_resource>(std::max<size_t>(uses, 1) * sizeof(LoweredAccess));
  }

  // A pass's accesses when every input is linked: one per use, or per component of a bundle
  // it uses whole. Reserved exactly, a pass's list never moves within the arena.
  static size_t most_accesses(const NodeSchema& s, const PassSpec& pass) {
    size_t count = 0;
    for (const PassUse& use : pass.uses) {
      const PortSpec& port = use.target == PassUse::Target::input    ? s.inputs[use.index]
                             : use.target == PassUse::Target::output ? s.outputs[use.index]
                                                                     : s.resources[use.index];
      count += use.component >= 0 ? 1 : port.type.components().size();
    }
    return count;
  }

  // An optional output (a debug view) is written only while something reads it: a link, the
  // file's outputs, or a dump (keep_optional_).
  void mark_wanted_outputs() {
    wanted_.assign(ports_.size(), keep_optional_ ? 1 : 0);
    for (const ResolvedLink& l : r_.links)
      if (l.from_node >= 0 && l.from_port >= 0) wanted_[port_base_[l.from_node] + l.from_port] = 1;
    for (auto [node, output] : r_.outputs) wanted_[port_base_[node] + output] = 1;
  }

  std::string_view id(int n) const { return r_.id(n); }
  Span& port(int node, int output) { return ports_[port_base_[node] + output]; }

  Span source_of(int link) {
    const ResolvedLink& l = r_.links[link];
    return port(l.from_node, l.from_port);
  }

  void forward(int n) {
    for (int o = 0; o < port_base_[n + 1] - port_base_[n]; ++o) {
      const int in = forwarded_input(r_, s_, n, o);
      if (int li = in >= 0 ? r_.nodes[n].input_link[in] : -1; li >= 0) port(n, o) = source_of(li);
    }
  }

  void add_output(int node, std::string port, Span span) {
    LoweredOutput& out = out_.outputs.emplace_back(LoweredOutput{node, std::move(port), {}});
    for (int c = 0; c < span.count; ++c) out.resources.push_back(span[c]);
  }

  void export_resources(Span span) {
    for (int c = 0; c < span.count; ++c)
      if (out_.resources[span[c]].lifetime == ResourceLifetime::transient)
        out_.resources[span[c]].lifetime = ResourceLifetime::exported;
  }

  std::optional<double> number_param(int n, int param) const {
    const JsonValue& v = r_.nodes[n].param(param);
    return v.is_number() ? std::optional<double>(v.as_number()) : std::nullopt;
  }

  // Width, height, layers and mips of an output or internal resource of node n.
  void size(int n, const PortSpec& spec, LoweredResource& res) {
    const SizeRule& rule = spec.size;
    double w = frame_.width, h = frame_.height;
    const ResolvedNode& rn = r_.nodes[n];
    switch (rule.from) {
      case SizeRule::From::frame:
        break;
      case SizeRule::From::fixed:
        w = rule.fixed[0], h = rule.fixed[1];
        break;
      case SizeRule::From::input: {
        int li = rn.input_link[rule.ref];
        if (li >= 0 && !source_of(li).empty()) {
          const LoweredResource& src = out_.resources[source_of(li).first];
          w = src.width, h = src.height;
        }
        break;
      }
      case SizeRule::From::param: {
        const JsonValue& v = rn.param(rule.ref);
        if (v.is_array() && v.items().size() == 2)
          w = v.items()[0].as_number(), h = v.items()[1].as_number();
        else if (v.is_number())
          w = h = v.as_number();
        break;
      }
    }
    double scale = rule.scale_param >= 0 ? number_param(n, rule.scale_param).value_or(1) : rule.scale;
    res.width = texels(w * scale);
    res.height = texels(h * scale);
    if (rule.only_when_scaled && scale >= 1) res.width = res.height = 1;
    res.layers = res.kind == ResourceKind::cube ? 6 : 1;
    // A 3D texture's depth rides in layers (runtime/gpu/plan_resources.cpp), not scaled.
    if (res.kind == ResourceKind::texture3d)
      res.layers = rule.depth_param >= 0 ? texels(number_param(n, rule.depth_param).value_or(1)) : rule.depth_fixed;
    uint32_t full = full_mip_count(res.width, res.height);
    if (res.kind == ResourceKind::texture3d) full = std::max(full, full_mip_count(res.layers, 1));
    switch (rule.mips) {
      case SizeRule::Mips::one:
        res.mips = 1;
        break;
      case SizeRule::Mips::full:
        res.mips = full;
        break;
      case SizeRule::Mips::param:
        res.mips = std::min(full, static_cast<uint32_t>(number_param(n, rule.mips_param).value_or(1)));
        break;
      case SizeRule::Mips::fixed:
        res.mips = std::min(full, rule.mips_fixed);
        break;
    }
    if (res.kind == ResourceKind::buffer) {
      uint32_t elements = 1;
      if (rule.sh_order_param >= 0) {
        uint32_t order = static_cast<uint32_t>(number_param(n, rule.sh_order_param).value_or(2));
        elements = (order + 1) * (order + 1);
      }
      res.width = elements, res.height = 1, res.mips = 1;
    }
    if (res.width > limits::max_image_extent || res.height > limits::max_image_extent ||
        (res.kind == ResourceKind::texture3d && res.layers > limits::max_image_extent)) [[unlikely]]
      too_large(n, res);
  }

  // The reports below are kept out of line: inlined, their strings made every call of the
  // functions above set up a large stack frame.
  [[gnu::noinline]] void too_large(int n, const LoweredResource& res) {
    d_.error(r_.graph->nodes[n].pos, json_pointer_append("/nodes", static_cast<size_t>(n)),
             "'" + res.name + "' would be " + std::to_string(res.width) + "x" + std::to_string(res.height) +
                 (res.kind == ResourceKind::texture3d ? "x" + std::to_string(res.layers) : "") + ", beyond the limit of " + std::to_string(limits::max_image_extent) + " texels a side");
  }

  // Named "<node><separator><port>", and ".<component>" after that for a bundle's parts.
  Span make_resources(int n, const PortSpec& spec, std::string_view separator) {
    Span span{static_cast<int>(out_.resources.size()), 0};
    for (const PortComponent& c : spec.type.components()) {
      LoweredResource& res = out_.resources.emplace_back();  // built in place: no copy to move and destroy
      res.name =
          c.name.empty() ? joined({id(n), separator, spec.name}) : joined({id(n), separator, spec.name, ".", c.name});
      res.node = n;
      res.kind = spec.type.resource;
      res.format = c.format;
      res.depth_format = c.depth;
      size(n, spec, res);
      res.bytes = resource_bytes_for(res, c.bytes_per_texel);
      ++span.count;
    }
    return span;
  }

  static uint64_t resource_bytes_for(const LoweredResource& r, uint32_t bytes_per_texel) {
    uint64_t texels = 0;
    const bool volume = r.kind == ResourceKind::texture3d;  // its depth halves with each mip
    for (uint32_t m = 0; m < r.mips; ++m)
      texels += uint64_t{std::max(1u, r.width >> m)} * std::max(1u, r.height >> m) *
                (volume ? std::max(1u, r.layers >> m) : 1u);
    return texels * (volume ? 1u : r.layers) * bytes_per_texel;
  }

  // A bypassed node that forwards an unlinked input leaves its consumers with nothing; one that
  // forwards nothing (null), or an optional input of its own that gets nothing, leaves optional
  // inputs unlinked.
  void check_fed(int n, int input, int link) {
    if (link < 0 || r_.links[link].history || !source_of(link).empty()) [[likely]]
      return;
    const ResolvedLink& l = r_.links[link];
    const int forwarded = forwarded_input(r_, s_, l.from_node, l.from_port);
    if (r_.nodes[n].schema->inputs[input].optional &&
        (forwarded < 0 || r_.nodes[l.from_node].schema->inputs[forwarded].optional))
      return;
    not_fed(n, input, link);
  }

  [[gnu::noinline]] void not_fed(int n, int input, int link) {
    const ResolvedLink& l = r_.links[link];
    const NodeSchema& producer = *r_.nodes[l.from_node].schema;
    int forwarded = forwarded_input(r_, s_, l.from_node, l.from_port);
    d_.error(r_.graph->links[l.source].to_pos, json_pointer_append("/links", static_cast<size_t>(l.source)) + "/to",
             "input '" + joined({id(n), ".", r_.nodes[n].schema->inputs[input].name}) + "' gets nothing: '" +
                 std::string(id(l.from_node)) + "' is bypassed (" + s_[l.from_node].reason + ") and " +
                 (forwarded < 0 ? std::string("forwards nothing")
                                : "its input '" + producer.inputs[forwarded].name + "' is not linked"));
  }

  void lower_node(int n) {
    const ResolvedNode& rn = r_.nodes[n];
    const NodeSchema& s = *rn.schema;
    LoweredNode& node = out_.nodes[n];
    for (size_t i = 0; i < s.inputs.size(); ++i) check_fed(n, static_cast<int>(i), rn.input_link[i]);

    // Static when the schema says so (and its static_unless param is 0) and every input is
    // static; the key covers the type, the params and the inputs' keys, so it changes whenever
    // the result could.
    bool is_static = s.is_static && (s.static_unless_param < 0 || number_param(n, s.static_unless_param) == 0.0);
    uint64_t key = 0;
    if (is_static) {
      const JsonValue& params = out_.static_params.emplace_back(n, node_params(r_, n, roots_)).second;
      key = fnv1a(write_json_compact(params), fnv1a(s.type));
      for (int li : rn.input_link) {
        if (li < 0) continue;
        if (r_.links[li].history) {
          is_static = false;
          break;
        }
        Span source = source_of(li);
        for (int c = 0; c < source.count; ++c) {
          const LoweredNode& producer = out_.nodes[out_.resources[source[c]].node];
          is_static &= producer.is_static;
          char digits[24];
          key = fnv1a(std::string_view(digits, std::to_chars(digits, digits + sizeof digits, producer.cache_key).ptr),
                      key);
        }
      }
    }
    node.is_static = is_static;
    node.cache_key = is_static ? key : 0;

    for (size_t o = 0; o < s.outputs.size(); ++o) {
      Span span = port(n, static_cast<int>(o)) = make_resources(n, s.outputs[o], ".");
      if (is_static)
        for (int c = 0; c < span.count; ++c) out_.resources[span[c]].lifetime = ResourceLifetime::cached;
    }
    size_t first_pass = out_.passes.size();
    internal_.clear();
    for (const auto& spec : s.resources) internal_.push_back(make_resources(n, spec, "/"));

    bool dropped_any = false;
    for (size_t p = 0; p < s.passes.size(); ++p) {
      if (!s_[n].why_dropped(p).empty()) {
        dropped_any = true;
        continue;
      }
      const PassSpec& spec = s.passes[p];
      LoweredPass pass{.name = joined({id(n), "/", spec.name}),
                       .accesses = std::pmr::vector<LoweredAccess>(out_.arena.get()),
                       .cache_key = is_static ? fnv1a(spec.name, key) : 0,
                       .node = n,
                       .pass = static_cast<int>(p),
                       .queue = spec.queue,
                       .is_static = is_static};
      int pass_index = static_cast<int>(out_.passes.size());
      pass.accesses.reserve(most_accesses(s, spec));
      for (const PassUse& use : spec.uses) {
        Span span;
        if (use.target == PassUse::Target::output) {
          if (s.outputs[use.index].optional && !wanted_[port_base_[n] + use.index]) continue;
          span = port(n, use.index);
        }
        else if (use.target == PassUse::Target::internal)
          span = internal_[use.index];
        else if (int li = rn.input_link[use.index]; li >= 0) {
          if (r_.links[li].history) {
            deferred_history_.emplace_back(pass_index, pass.accesses.size(), li);
            pass.accesses.push_back({-1, use.usage, use.target, use.index, use.component});
            continue;
          }
          span = source_of(li);
        }
        for (int c = 0; c < span.count; ++c)  // none for an optional input left unlinked
          if (use.component < 0 || use.component == c)
            pass.accesses.push_back({span[c], use.usage, use.target, use.index, c});
      }
      out_.passes.push_back(std::move(pass));
    }
    if (dropped_any) drop_unwritten_internal_reads(first_pass);
  }

  // A dropped pass (say, shadows in a scene without shadow casters) leaves internal resources
  // that nothing writes: later passes of the node must not read them, so they go unbound.
  void drop_unwritten_internal_reads(size_t first_pass) {
    std::vector<int> written;
    for (size_t p = first_pass; p < out_.passes.size(); ++p)
      for (const auto& a : out_.passes[p].accesses)
        if (a.target == PassUse::Target::internal && usage_writes(a.usage)) written.push_back(a.resource);
    for (size_t p = first_pass; p < out_.passes.size(); ++p)
      std::erase_if(out_.passes[p].accesses, [&](const LoweredAccess& a) {
        return a.target == PassUse::Target::internal &&
               std::find(written.begin(), written.end(), a.resource) == written.end();
      });
  }

  // A history input reads a previous-frame copy of its source, made once per source port.
  void bind_history(int pass, size_t slot, int link) {
    const ResolvedLink& l = r_.links[link];
    Span& previous = previous_[port_base_[l.from_node] + l.from_port];
    Span current = port(l.from_node, l.from_port);
    if (previous.empty()) {
      previous.first = static_cast<int>(out_.resources.size());
      for (int c = 0; c < current.count; ++c) {
        out_.resources[current[c]].lifetime = ResourceLifetime::history;
        LoweredResource copy = out_.resources[current[c]];
        copy.name += "@previous";
        copy.history_of = current[c];
        out_.resources.push_back(std::move(copy));
        ++previous.count;
      }
    }
    auto& accesses = out_.passes[pass].accesses;
    LoweredAccess placeholder = accesses[slot];  // its component: one, or -1 for all
    accesses.erase(accesses.begin() + static_cast<long>(slot));
    for (int c = previous.count; c-- > 0;) {
      if (placeholder.component >= 0 && placeholder.component != c) continue;
      LoweredAccess a = placeholder;
      a.resource = previous[c];
      a.component = c;
      accesses.insert(accesses.begin() + static_cast<long>(slot), a);
    }
  }
};

}  // namespace

JsonValue node_params(const ResolvedGraph& resolved, int node, const AssetRoots& roots) {
  const ResolvedNode& rn = resolved.nodes[node];
  JsonValue params = JsonValue::object();
  params.members().reserve(rn.params.size());
  for (size_t p = 0; p < rn.params.size(); ++p) {
    const ParamSpec& spec = rn.schema->params[p];
    const JsonValue& value = *rn.params[p];
    std::optional<std::string> path;
    if (spec.type == ParamType::path && value.is_string())
      path = resolve_asset_path(resolved.graph->file, value.as_string(), roots, spec.extensions, nullptr);
    params.members().emplace_back(spec.name, path ? JsonValue(*path) : value);  // schema names are unique
  }
  return params;
}

std::string_view lifetime_name(ResourceLifetime l) {
  constexpr std::string_view names[] = {"transient", "exported", "cached", "history"};
  return names[static_cast<int>(l)];
}

std::optional<LoweredGraph> lower(const ResolvedGraph& resolved, const CachedVector<int>& topo_order,
                                  const NodeStates& states, FrameSize frame, const AssetRoots& roots,
                                  Diagnostics& diagnostics, bool keep_optional_outputs) {
  size_t before = diagnostics.error_count();
  LoweredGraph out = Lowerer(resolved, states, frame, roots, keep_optional_outputs, diagnostics).run(topo_order);
  if (diagnostics.error_count() > before) return std::nullopt;
  return out;
}

JsonValue dump_lowered(const LoweredGraph& lowered) {
  JsonValue out = JsonValue::object();
  JsonValue& passes = out.set("passes", JsonValue::array());
  for (const auto& p : lowered.passes) {
    JsonValue& pass = passes.push(JsonValue::object());
    pass.set("name", p.name);
    JsonValue& uses = pass.set("uses", JsonValue::object());
    for (const auto& a : p.accesses) uses.set(lowered.resources[a.resource].name, std::string(usage_name(a.usage)));
    if (p.is_static) pass.set("static", true);
  }
  JsonValue& resources = out.set("resources", JsonValue::array());
  for (const auto& r : lowered.resources) {
    JsonValue& res = resources.push(JsonValue::object());
    res.set("name", r.name);
    res.set("format", std::string(r.format));
    JsonValue extent = JsonValue::array();
    extent.push(static_cast<int64_t>(r.width));
    extent.push(static_cast<int64_t>(r.height));
    res.set("extent", extent);
    res.set("layers", static_cast<int64_t>(r.layers));
    res.set("mips", static_cast<int64_t>(r.mips));
    res.set("bytes", r.bytes);
    res.set("lifetime", std::string(lifetime_name(r.lifetime)));
  }
  return out;
}

}  // namespace lg
