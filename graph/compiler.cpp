#include "graph/compiler.h"

#include <chrono>
#include <cstdio>

#include "graph/compiler/cull.h"
#include "graph/compiler/lifetimes.h"
#include "graph/compiler/resolve.h"
#include "graph/compiler/schedule.h"
#include "graph/compiler/specialize.h"
#include "graph/compiler/synchronize.h"
#include "graph/compiler/validate.h"

namespace lg {
namespace {

class PhaseTimer {
 public:
  explicit PhaseTimer(CompileResult& result) : result_(result) {}
  template <class F>
  auto run(const char* phase, F&& f) {
    auto start = std::chrono::steady_clock::now();
    auto value = f();
    auto end = std::chrono::steady_clock::now();
    result_.timings.push_back({phase, std::chrono::duration<double, std::milli>(end - start).count()});
    return value;
  }

 private:
  CompileResult& result_;
};

std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string slot_name(const NodeSchema& s, const LoweredAccess& a) {
  switch (a.target) {
    case PassUse::Target::input: return "in." + s.inputs[a.port].name;
    case PassUse::Target::output: return "out." + s.outputs[a.port].name;
    case PassUse::Target::internal: return "tmp." + s.resources[a.port].name;
  }
  return {};
}

Plan assemble(const Graph& graph, const ResolvedGraph& resolved, const NodeStates& states, LoweredGraph&& lowered,
              const std::vector<int>& node_order, const std::vector<int>& order, const std::vector<Lifetime>& lives, MemoryLayout&& memory,
              std::vector<Barrier> barriers, const CompileOptions& options) {
  Plan plan;
  plan.name = graph.name;
  plan.file = graph.file;
  plan.scene = options.scene.name;
  plan.frame = options.frame;
  // Nodes in topological order (ties by id), so the plan does not depend on the file's order.
  std::vector<int> plan_index(graph.nodes.size());
  for (size_t k = 0; k < node_order.size(); ++k) plan_index[node_order[k]] = static_cast<int>(k);
  for (int n : node_order) {
    const NodeSchema& s = *resolved.nodes[n].schema;
    PlanNode node{graph.nodes[n].id, s.type, states[n].kind, states[n].reason, {}, JsonValue::object(),
                  lowered.nodes[n].is_static};
    if (states[n].kind == NodeState::Kind::active) node.params = node_params(resolved, n, options.roots);
    for (size_t p = 0; p < s.passes.size(); ++p)
      if (!states[n].dropped_passes[p].empty()) node.dropped.emplace_back(s.passes[p].name, states[n].dropped_passes[p]);
    plan.nodes.push_back(std::move(node));
  }
  for (int index : order) {
    LoweredPass& lp = lowered.passes[index];
    const NodeSchema& s = *resolved.nodes[lp.node].schema;
    PlanPass pass{std::move(lp.name), plan_index[lp.node], s.passes[lp.pass].name, lp.queue, {}, lp.is_static, lp.is_static ? hex(lp.cache_key) : ""};
    for (const auto& a : lp.accesses) pass.accesses.push_back({a.resource, a.usage, slot_name(s, a), a.component});
    plan.passes.push_back(std::move(pass));
  }
  plan.resources.reserve(lowered.resources.size());
  for (size_t r = 0; r < lowered.resources.size(); ++r) {
    auto lifetime = lowered.resources[r].lifetime;
    bool persistent = lifetime == ResourceLifetime::cached || lifetime == ResourceLifetime::history;
    if (lives[r].used() && !persistent) plan.memory.transient_unaliased += lowered.resources[r].bytes;
    plan.resources.push_back({std::move(lowered.resources[r]), lives[r].first, lives[r].last, std::move(memory.placements[r])});
    plan.resources.back().desc.node = plan_index[plan.resources.back().desc.node];
  }
  plan.passes.reserve(order.size());
  plan.blocks = memory.blocks;
  plan.memory.transient = memory.blocks[0].size;
  plan.memory.persistent = memory.blocks[1].size;
  plan.barriers = std::move(barriers);
  return plan;
}

JsonValue order_dump(const LoweredGraph& lowered, const std::vector<int>& order) {
  JsonValue out = JsonValue::array();
  for (int p : order) out.push(lowered.passes[p].name);
  return out;
}

JsonValue lifetimes_dump(const LoweredGraph& lowered, const std::vector<Lifetime>& lives) {
  JsonValue out = JsonValue::object();
  for (size_t r = 0; r < lives.size(); ++r) {
    JsonValue range = JsonValue::array();
    range.push(lives[r].first);
    range.push(lives[r].last);
    out.set(lowered.resources[r].name, range);
  }
  return out;
}

JsonValue barriers_dump(const LoweredGraph& lowered, const std::vector<int>& order, const std::vector<Barrier>& barriers) {
  JsonValue out = JsonValue::array();
  for (const auto& b : barriers) {
    JsonValue& item = out.push(JsonValue::object());
    item.set("before", lowered.passes[order[b.before]].name);
    item.set("resource", lowered.resources[b.resource].name);
    item.set("reason", std::string(barrier_reason_name(b.reason)));
    item.set("src", stage_names(b.src_stages) + " " + access_names(b.src_access));
    item.set("dst", stage_names(b.dst_stages) + " " + access_names(b.dst_access));
    item.set("layout", std::string(layout_name(b.old_layout)) + " -> " + std::string(layout_name(b.new_layout)));
  }
  return out;
}

}  // namespace

CompileResult compile(const Graph& graph, const Registry& registry, const CompileOptions& options,
                      Diagnostics& diagnostics) {
  CompileResult result;
  PhaseTimer timer(result);
  auto dump = [&](const char* phase, auto&& make) {
    if (options.keep_dumps) result.dumps.emplace_back(phase, make());
  };

  ResolvedGraph resolved = timer.run("resolve", [&] { return resolve(graph, registry, diagnostics); });
  dump("resolve", [&] { return dump_resolved(resolved); });
  auto order_nodes = timer.run("validate", [&] { return validate(resolved, options.roots, diagnostics); });
  if (!order_nodes || diagnostics.has_errors()) return result;

  NodeStates states = timer.run("specialize", [&] { return specialize(resolved, options.scene); });
  dump("specialize", [&] { return dump_node_states(resolved, states); });
  states = timer.run("cull", [&] { return cull(resolved, std::move(states)); });
  dump("cull", [&] { return dump_node_states(resolved, states); });

  auto lowered = timer.run("lower", [&] { return lower(resolved, *order_nodes, states, options.frame, options.roots, diagnostics); });
  if (!lowered) return result;
  dump("lower", [&] { return dump_lowered(*lowered); });
  auto order = timer.run("schedule", [&] { return schedule(*lowered); });
  dump("schedule", [&] { return order_dump(*lowered, order); });
  auto lives = timer.run("lifetimes", [&] { return lifetimes(*lowered, order); });
  dump("lifetimes", [&] { return lifetimes_dump(*lowered, lives); });
  auto memory = timer.run("alias", [&] { return alias(*lowered, lives, options.alias); });
  dump("alias", [&] { return dump_memory(*lowered, memory); });
  auto barriers = timer.run("synchronize", [&] { return synchronize(*lowered, order, memory); });
  dump("synchronize", [&] { return barriers_dump(*lowered, order, barriers); });

  result.plan = timer.run("assemble", [&] {
    return assemble(graph, resolved, states, std::move(*lowered), *order_nodes, order, lives, std::move(memory), std::move(barriers), options);
  });
  return result;
}

}  // namespace lg
