#include "runtime/exec/frame_stats.h"

#include <cstdio>

#include "graph/plan_format.h"

namespace lg {
namespace {

std::string milliseconds(double ms) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", ms);
  return buf;
}

std::string pad(std::string s, size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

}  // namespace

FrameStats plan_stats(const Plan& plan) {
  FrameStats stats;
  stats.plan_memory = plan.memory;
  for (const PlanNode& n : plan.nodes) {
    if (n.state != NodeState::Kind::active) stats.skipped_nodes.push_back({n.id, n.type, n.state, n.reason});
    for (const auto& [pass, why] : n.dropped) stats.dropped_passes.push_back({n.id + "/" + pass, n.type, why});
  }
  return stats;
}

JsonValue frame_stats_json(const FrameStats& stats) {
  JsonValue root = JsonValue::object();
  root.set("format", "lumagraph-frame-stats/1");
  root.set("frame", stats.frame);
  root.set("gpu_ms", stats.gpu_ms);
  root.set("cpu_ms", stats.cpu_ms);
  JsonValue& passes = root.set("passes", JsonValue::array());
  for (const PassStats& p : stats.passes) {
    JsonValue& pass = passes.push(JsonValue::object());
    pass.set("name", p.name);
    pass.set("gpu_ms", p.gpu_ms);
    if (p.cached) pass.set("cached", true);
  }
  JsonValue& memory = root.set("memory", JsonValue::object());
  memory.set("device_bytes_used", stats.device_memory_used);
  memory.set("transient_bytes", stats.plan_memory.transient);
  memory.set("transient_bytes_without_aliasing", stats.plan_memory.transient_unaliased);
  memory.set("persistent_bytes", stats.plan_memory.persistent);
  JsonValue& nodes = root.set("skipped_nodes", JsonValue::array());
  for (const SkippedNode& n : stats.skipped_nodes) {
    JsonValue& node = nodes.push(JsonValue::object());
    node.set("id", n.id);
    node.set("type", n.type);
    node.set("state", std::string(node_state_name(n.state)));
    node.set("reason", n.reason);
  }
  JsonValue& dropped = root.set("dropped_passes", JsonValue::array());
  for (const DroppedPass& d : stats.dropped_passes) {
    JsonValue& pass = dropped.push(JsonValue::object());
    pass.set("pass", d.pass);
    pass.set("type", d.type);
    pass.set("reason", d.reason);
  }
  return root;
}

std::string frame_stats_text(const FrameStats& stats) {
  std::string out = "frame " + std::to_string(stats.frame) + ": GPU " + milliseconds(stats.gpu_ms) + " ms, CPU " +
                    milliseconds(stats.cpu_ms) + " ms\n\n";
  out += pad("  #", 5) + pad("pass", 28) + "GPU ms\n";
  for (size_t p = 0; p < stats.passes.size(); ++p) {
    const PassStats& pass = stats.passes[p];
    out += pad("  " + std::to_string(p), 5) + pad(pass.name, 28) +
           (pass.cached ? std::string("cached") : milliseconds(pass.gpu_ms)) + "\n";
  }
  out += "memory: device " + format_bytes(stats.device_memory_used) + "; plan transient " +
         format_bytes(stats.plan_memory.transient) + " (" + format_bytes(stats.plan_memory.transient_unaliased) +
         " without aliasing), persistent " + format_bytes(stats.plan_memory.persistent) + "\n";
  std::string bypassed, culled;
  for (const SkippedNode& n : stats.skipped_nodes)
    (n.state == NodeState::Kind::culled ? culled : bypassed) += "  " + n.id + " (" + n.type + "): " + n.reason + "\n";
  if (!bypassed.empty()) out += "bypassed:\n" + bypassed;
  if (!culled.empty()) out += "culled:\n" + culled;
  if (!stats.dropped_passes.empty()) {
    out += "passes dropped:\n";
    for (const DroppedPass& d : stats.dropped_passes) out += "  " + d.pass + " (" + d.type + "): " + d.reason + "\n";
  }
  return out;
}

}  // namespace lg
