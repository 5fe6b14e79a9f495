#include "graph/plan_format.h"

#include <cstdio>

#include "graph/json_writer.h"

namespace lg {
namespace {

std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string_view queue_name(Queue q) {
  return q == Queue::compute ? "compute" : "graphics";
}

JsonValue int_pair(int64_t a, int64_t b) {
  JsonValue v = JsonValue::array();
  v.push(a);
  v.push(b);
  return v;
}

std::string pad(std::string s, size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

std::string percent(double part, double whole) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f%%", whole > 0 ? 100.0 * part / whole : 0.0);
  return buf;
}

}  // namespace

std::string format_bytes(uint64_t bytes) {
  char buf[32];
  if (bytes >= (1ull << 20))
    std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
  else if (bytes >= 1024)
    std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(bytes) / 1024);
  else
    std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
  return buf;
}

JsonValue plan_to_json(const Plan& plan) {
  JsonValue root = JsonValue::object();
  root.set("format", "lumagraph-plan/1");
  root.set("name", plan.name);
  root.set("file", plan.file);
  root.set("scene", plan.scene);
  root.set("frame", int_pair(plan.frame.width, plan.frame.height));
  if (plan.jitter_grid[0] > 0) root.set("jitter_grid", int_pair(plan.jitter_grid[0], plan.jitter_grid[1]));

  JsonValue& nodes = root.set("nodes", JsonValue::array());
  for (const auto& n : plan.nodes) {
    JsonValue& node = nodes.push(JsonValue::object());
    node.set("id", n.id);
    node.set("type", n.type);
    node.set("state", std::string(node_state_name(n.state)));
    if (!n.reason.empty()) node.set("reason", n.reason);
    if (!n.dropped.empty()) {
      JsonValue& dropped = node.set("dropped_passes", JsonValue::object());
      for (const auto& [pass, why] : n.dropped) dropped.set(pass, why);
    }
    if (n.state == NodeState::Kind::active) {
      node.set("params", n.params);
      if (n.is_static) node.set("static", true);
    }
  }

  JsonValue& passes = root.set("passes", JsonValue::array());
  for (const auto& p : plan.passes) {
    JsonValue& pass = passes.push(JsonValue::object());
    pass.set("name", p.name);
    pass.set("node", plan.nodes[p.node].id);
    pass.set("pass", p.pass);
    pass.set("queue", std::string(queue_name(p.queue)));
    if (p.is_static) pass.set("cache_key", hex(p.cache_key));
    JsonValue& uses = pass.set("uses", JsonValue::array());
    for (const auto& a : plan.accesses_of(p)) {
      JsonValue& use = uses.push(JsonValue::object());
      use.set("resource", plan.resources[a.resource].desc.name);
      use.set("slot", plan.slot_of(a));
      use.set("usage", std::string(usage_name(a.usage)));
    }
  }

  JsonValue& resources = root.set("resources", JsonValue::array());
  for (const auto& r : plan.resources) {
    JsonValue& res = resources.push(JsonValue::object());
    res.set("name", r.desc.name);
    res.set("format", std::string(r.desc.format));
    res.set("extent", int_pair(r.desc.width, r.desc.height));
    res.set("layers", static_cast<int64_t>(r.desc.layers));
    res.set("mips", static_cast<int64_t>(r.desc.mips));
    res.set("bytes", r.desc.bytes);
    res.set("lifetime", std::string(lifetime_name(r.desc.lifetime)));
    if (r.first < 0) {
      res.set("unused", true);
      continue;
    }
    res.set("passes", int_pair(r.first, r.last));
    res.set("block", r.placement.block);
    res.set("offset", r.placement.offset);
    if (r.desc.history_of >= 0) res.set("previous_frame_of", plan.resources[r.desc.history_of].desc.name);
  }

  JsonValue& barriers = root.set("barriers", JsonValue::array());
  for (const auto& b : plan.barriers) {
    JsonValue& barrier = barriers.push(JsonValue::object());
    barrier.set("before", plan.passes[b.before].name);
    barrier.set("resource", plan.resources[b.resource].desc.name);
    barrier.set("reason", std::string(barrier_reason_name(b.reason)));
    barrier.set("src_stages", stage_names(b.src_stages));
    barrier.set("src_access", access_names(b.src_access));
    barrier.set("dst_stages", stage_names(b.dst_stages));
    barrier.set("dst_access", access_names(b.dst_access));
    if (b.new_layout != Layout::none) {
      barrier.set("old_layout", std::string(layout_name(b.old_layout)));
      barrier.set("new_layout", std::string(layout_name(b.new_layout)));
    }
    if (b.skip_when_cached) barrier.set("skip_when_cached", true);
  }

  JsonValue& outputs = root.set("outputs", JsonValue::array());
  for (const auto& o : plan.outputs) {
    JsonValue& output = outputs.push(JsonValue::object());
    if (o.node >= 0) output.set("node", plan.nodes[o.node].id);
    output.set("port", o.port);
    JsonValue& names = output.set("resources", JsonValue::array());
    for (int r : o.resources) names.push(plan.resources[r].desc.name);
  }

  JsonValue& memory = root.set("memory", JsonValue::object());
  JsonValue& blocks = memory.set("blocks", JsonValue::array());
  for (const auto& b : plan.blocks) {
    JsonValue& block = blocks.push(JsonValue::object());
    block.set("bytes", b.size);
    block.set("aliased", b.aliased);
  }
  memory.set("transient_bytes", plan.memory.transient);
  memory.set("transient_bytes_without_aliasing", plan.memory.transient_unaliased);
  memory.set("persistent_bytes", plan.memory.persistent);
  return root;
}

std::string plan_to_dot(const Plan& plan) {
  std::string out = "digraph " + json_quote(plan.name.empty() ? "plan" : plan.name) + " {\n";
  out += "  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n";
  for (size_t p = 0; p < plan.passes.size(); ++p) {
    const PlanPass& pass = plan.passes[p];
    out += "  p" + std::to_string(p) + " [shape=box, style=\"rounded,filled\", fillcolor=\"" +
           (pass.is_static ? "#d9ead3" : "#cfe2f3") +
           "\", label=" + json_quote(std::to_string(p) + ": " + pass.name + (pass.is_static ? "\n(cached)" : "")) +
           "];\n";
  }
  for (size_t r = 0; r < plan.resources.size(); ++r) {
    const PlanResource& res = plan.resources[r];
    if (res.first < 0) continue;
    out += "  r" + std::to_string(r) + " [shape=note, label=" +
           json_quote(res.desc.name + "\n" + std::string(res.desc.format) + " " + std::to_string(res.desc.width) + "x" +
                      std::to_string(res.desc.height) + "\n" + format_bytes(res.desc.bytes)) +
           "];\n";
  }
  for (size_t p = 0; p < plan.passes.size(); ++p)
    for (const auto& a : plan.accesses_of(plan.passes[p])) {
      std::string pass = "p" + std::to_string(p), res = "r" + std::to_string(a.resource);
      if (usage_writes(a.usage)) out += "  " + pass + " -> " + res + ";\n";
      if (usage_reads(a.usage))
        out += "  " + res + " -> " + pass + (usage_writes(a.usage) ? " [style=dashed]" : "") + ";\n";
    }
  for (size_t n = 0; n < plan.nodes.size(); ++n) {
    const PlanNode& node = plan.nodes[n];
    if (node.state == NodeState::Kind::active) continue;
    out += "  skipped" + std::to_string(n) + " [shape=box, style=dashed, fontcolor=gray40, label=" +
           json_quote(node.id + " (" + std::string(node_state_name(node.state)) + ")\n" + node.reason) + "];\n";
  }
  return out + "}\n";
}

std::string plan_to_text(const Plan& plan) {
  std::string out = "plan '" + (plan.name.empty() ? std::string("unnamed") : plan.name) + "'";
  if (!plan.file.empty()) out += " from " + plan.file;
  out += ", scene '" + plan.scene + "', frame " + std::to_string(plan.frame.width) + "x" +
         std::to_string(plan.frame.height);
  if (plan.jitter_grid[0] > 0)
    out += ", camera jittered on " + std::to_string(plan.jitter_grid[0]) + "x" + std::to_string(plan.jitter_grid[1]);
  out += "\n\n";

  out += pad("  #", 5) + pad("pass", 28) + pad("queue", 10) + pad("cache", 8) + pad("barriers", 10) + "writes\n";
  std::vector<int> barrier_count(plan.passes.size(), 0);
  for (const auto& b : plan.barriers) ++barrier_count[b.before];
  for (size_t p = 0; p < plan.passes.size(); ++p) {
    const PlanPass& pass = plan.passes[p];
    std::string writes;
    for (const auto& a : plan.accesses_of(pass))
      if (usage_writes(a.usage)) writes += (writes.empty() ? "" : ", ") + plan.resources[a.resource].desc.name;
    out += pad("  " + std::to_string(p), 5) + pad(pass.name, 28) + pad(std::string(queue_name(pass.queue)), 10) +
           pad(pass.is_static ? "static" : "-", 8) + pad(std::to_string(barrier_count[p]), 10) + writes + "\n";
  }

  std::string bypassed, dropped, culled;
  for (const auto& n : plan.nodes) {
    std::string who = "  " + n.id + " (" + n.type + ")";
    if (n.state == NodeState::Kind::bypassed) bypassed += who + ": " + n.reason + "\n";
    if (n.state == NodeState::Kind::culled) culled += who + ": " + n.reason + "\n";
    if (n.state == NodeState::Kind::active)
      for (const auto& [pass, why] : n.dropped)
        dropped += "  " + n.id + "/" + pass + " (" + n.type + "): " + why + "\n";
  }
  if (!bypassed.empty()) out += "\nbypassed:\n" + bypassed;
  if (!dropped.empty()) out += "\npasses dropped:\n" + dropped;
  if (!culled.empty()) out += "\nculled:\n" + culled;

  out += "\n" + pad("  resource", 30) + pad("format", 12) + pad("extent", 14) + pad("size", 12) + pad("lifetime", 11) +
         pad("passes", 9) + "offset\n";
  for (const auto& r : plan.resources) {
    if (r.first < 0) continue;
    std::string extent = std::to_string(r.desc.width) + "x" + std::to_string(r.desc.height);
    if (r.desc.layers > 1) extent += "x" + std::to_string(r.desc.layers);
    if (r.desc.mips > 1) extent += " m" + std::to_string(r.desc.mips);
    std::string where = (r.placement.block == 1 ? "P+" : "T+") + format_bytes(r.placement.offset);
    out += pad("  " + r.desc.name, 30) + pad(std::string(r.desc.format), 12) + pad(extent, 14) +
           pad(format_bytes(r.desc.bytes), 12) + pad(std::string(lifetime_name(r.desc.lifetime)), 11) +
           pad(std::to_string(r.first) + "-" + std::to_string(r.last), 9) + where + "\n";
  }

  const MemoryTotals& m = plan.memory;
  out += "\nmemory: transient " + format_bytes(m.transient) + " with aliasing, " + format_bytes(m.transient_unaliased) +
         " without (saves " +
         percent(static_cast<double>(m.transient_unaliased - std::min(m.transient, m.transient_unaliased)),
                 static_cast<double>(m.transient_unaliased)) +
         "); persistent " + format_bytes(m.persistent) + "; " + std::to_string(plan.barriers.size()) + " barriers\n";
  return out;
}

}  // namespace lg
