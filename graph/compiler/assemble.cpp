#include "graph/compiler/assemble.h"

#include <algorithm>
#include <unordered_map>

namespace lg {
namespace {

// Interns the slot names of the plan's accesses: each (schema, port) is spelled out once, the
// first time a pass uses it, so an access costs an index lookup instead of a string.
class SlotNames {
 public:
  explicit SlotNames(std::vector<std::string>& names) : names_(names) {}

  int of(const NodeSchema& s, const LoweredAccess& a) {
    // A pass's accesses share its schema: the map is asked once a pass, not once an access.
    if (&s != last_schema_) {
      auto [base, added] = base_.try_emplace(&s, ids_.size());
      if (added) ids_.resize(ids_.size() + s.inputs.size() + s.outputs.size() + s.resources.size(), -1);
      last_schema_ = &s;
      last_base_ = base->second;
    }
    const size_t at = last_base_ + a.port +
                      (a.target == PassUse::Target::input    ? 0
                       : a.target == PassUse::Target::output ? s.inputs.size()
                                                             : s.inputs.size() + s.outputs.size());
    if (ids_[at] < 0) ids_[at] = intern(spelled(s, a));
    return ids_[at];
  }

 private:
  std::vector<std::string>& names_;
  std::unordered_map<const NodeSchema*, size_t> base_;  // schema -> its first entry in ids_
  std::vector<int> ids_;                                // per schema port: index into names_, -1 until used
  const NodeSchema* last_schema_ = nullptr;             // the schema last asked for, and its base
  size_t last_base_ = 0;

  static std::string spelled(const NodeSchema& s, const LoweredAccess& a) {
    switch (a.target) {
      case PassUse::Target::input:
        return "in." + s.inputs[a.port].name;
      case PassUse::Target::output:
        return "out." + s.outputs[a.port].name;
      case PassUse::Target::internal:
        break;
    }
    return "tmp." + s.resources[a.port].name;
  }

  // Types share port names ("in.color"): one entry for each distinct name. Linear, as there
  // are few, and each is looked up once per schema port.
  int intern(std::string name) {
    auto it = std::find(names_.begin(), names_.end(), name);
    if (it != names_.end()) return static_cast<int>(it - names_.begin());
    names_.push_back(std::move(name));
    return static_cast<int>(names_.size()) - 1;
  }
};

// Releases a vector's memory now, not when its owner goes.
template <class T>
void release(T& container) {
  T().swap(container);
}

}  // namespace

// Built part by part, each IR released once the plan has what it keeps of it, and the plan's
// largest array (its nodes) made last: the plan reuses the IRs' memory instead of growing the
// heap past both, which the next compile would fault in again once the heap is trimmed.
Plan assemble(const Graph& graph, const ResolvedGraph& resolved, NodeStates&& states, LoweredGraph&& lowered,
              const CachedVector<int>& node_order, const CachedVector<int>& order, const CachedVector<Lifetime>& lives,
              MemoryLayout&& memory, CachedVector<Barrier> barriers, const AssembleOptions& options) {
  Plan plan;
  plan.name = graph.name;
  plan.file = graph.file;
  plan.scene = options.scene_name;
  plan.frame = options.frame;
  plan.keeps_every_output = options.keeps_every_output;
  // Nodes in topological order (ties by id), so the plan does not depend on the file's order.
  CachedVector<int> plan_index(graph.nodes.size());
  for (size_t k = 0; k < node_order.size(); ++k) plan_index[node_order[k]] = static_cast<int>(k);

  SlotNames slot_names(plan.slot_names);
  plan.accesses.reserve(lowered.access_count());
  plan.passes.reserve(order.size());
  for (int index : order) {
    LoweredPass& lp = lowered.passes[index];
    const NodeSchema& s = *resolved.nodes[lp.node].schema;
    plan.passes.emplace_back(std::move(lp.name), s.passes[lp.pass].name, lp.cache_key, plan_index[lp.node],
                             static_cast<uint32_t>(plan.accesses.size()), static_cast<uint32_t>(lp.accesses.size()),
                             lp.queue, lp.is_static);
    for (const auto& a : lp.accesses) {
      plan.accesses.emplace_back(a.resource, a.usage, slot_names.of(s, a), a.component);
      if (s.camera_jitter_input >= 0 && a.target == PassUse::Target::input && a.port == s.camera_jitter_input) {
        const LoweredResource& grid = lowered.resources[a.resource];
        plan.jitter_grid = {grid.width, grid.height};
      }
    }
  }
  release(lowered.passes);
  lowered.arena.reset();

  plan.resources.reserve(lowered.resources.size());
  for (size_t r = 0; r < lowered.resources.size(); ++r) {
    auto lifetime = lowered.resources[r].lifetime;
    bool persistent = lifetime == ResourceLifetime::cached || lifetime == ResourceLifetime::history;
    if (lives[r].used() && !persistent) plan.memory.transient_unaliased += memory.placements[r].size;
    plan.resources.emplace_back(std::move(lowered.resources[r]), lives[r].first, lives[r].last,
                                std::move(memory.placements[r]));
    plan.resources.back().desc.node = plan_index[plan.resources.back().desc.node];
  }
  release(lowered.resources);
  release(memory.placements);
  plan.blocks = memory.blocks;
  plan.predecessors = std::move(memory.predecessors);
  plan.memory.transient = memory.blocks[0].size;
  plan.memory.persistent = memory.blocks[1].size;
  plan.barriers = std::move(barriers);
  for (LoweredOutput& o : lowered.outputs)
    plan.outputs.push_back({o.node < 0 ? -1 : plan_index[o.node], std::move(o.port), std::move(o.resources)});

  plan.nodes.reserve(node_order.size());
  auto kept_params = lowered.static_params.begin();  // in lowering order, which is node_order
  for (int n : node_order) {
    const NodeSchema& s = *resolved.nodes[n].schema;
    JsonValue params = JsonValue::object();  // culled and bypassed nodes, and types without params
    if (kept_params != lowered.static_params.end() && kept_params->first == n)
      params = std::move(kept_params++->second);
    else if (states[n].kind == NodeState::Kind::active && !s.params.empty())
      params = node_params(resolved, n, options.roots);
    // Built in place (aggregates take parentheses in C++20): no temporary to move and destroy.
    PlanNode& node = plan.nodes.emplace_back(std::string(resolved.id(n)), s.type, std::move(states[n].reason),
                                             std::vector<std::pair<std::string, std::string>>{}, std::move(params),
                                             states[n].kind, lowered.nodes[n].is_static);
    for (size_t p = 0; p < s.passes.size(); ++p)
      if (auto why = states[n].why_dropped(p); !why.empty()) node.dropped.emplace_back(s.passes[p].name, why);
  }
  return plan;
}

}  // namespace lg
