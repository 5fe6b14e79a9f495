#include "graph/compiler/synchronize.h"

#include <algorithm>
#include <array>

namespace lg {
namespace {

// Consecutive accesses to one resource that need no barrier between them. A resource's groups
// are a linked list in one pool, in schedule order.
struct Group {
  int first = -1;  // schedule position of its first pass
  AccessInfo info;
  int next = -1;
};

AccessInfo merge(AccessInfo a, const AccessInfo& b) {
  a.stages |= b.stages;
  a.access |= b.access;
  a.writes |= b.writes;
  if (a.layout != b.layout) a.layout = Layout::general;
  return a;
}

BarrierReason reason_between(const AccessInfo& before, const AccessInfo& after) {
  if (before.writes && after.writes) return BarrierReason::write_after_write;
  if (before.writes) return BarrierReason::read_after_write;
  if (after.writes) return BarrierReason::write_after_read;
  return BarrierReason::layout_transition;
}

// Barriers by the pass they precede, in the order they were made (a counting sort: stable,
// linear, one buffer).
CachedVector<Barrier> sorted_by_pass(CachedVector<Barrier> barriers, size_t passes) {
  CachedVector<int> start(passes + 1, 0);
  for (const Barrier& b : barriers) ++start[b.before + 1];
  for (size_t p = 0; p < passes; ++p) start[p + 1] += start[p];
  CachedVector<Barrier> out(barriers.size());
  for (Barrier& b : barriers) out[start[b.before]++] = b;
  return out;
}

// What a pass's use of a resource means for synchronization: its stages, access, layout.
constexpr AccessInfo describe_access(Usage usage, Queue queue, bool buffer, bool depth) {
  const uint32_t shader = queue == Queue::compute ? stage_compute_shader : stage_fragment_shader;
  const Layout shader_layout = buffer ? Layout::none : Layout::general;
  const uint32_t depth_stages = stage_early_fragment_tests | stage_late_fragment_tests;
  const uint32_t depth_access = access_depth_stencil_attachment_read | access_depth_stencil_attachment_write;
  switch (usage) {
    case Usage::sampled:
      return {shader, access_shader_sampled_read, buffer ? Layout::none : Layout::read_only, false};
    case Usage::storage_read:
      return {shader, access_shader_storage_read, shader_layout, false};
    case Usage::storage_write:
      return {shader, access_shader_storage_write, shader_layout, true};
    case Usage::storage_read_write:
      return {shader, access_shader_storage_read | access_shader_storage_write, shader_layout, true};
    case Usage::attachment_write:
      if (depth) return {depth_stages, depth_access, Layout::attachment, true};
      return {stage_color_attachment_output, access_color_attachment_write, Layout::attachment, true};
    case Usage::attachment_blend:
      if (depth) return {depth_stages, depth_access, Layout::attachment, true};
      return {stage_color_attachment_output, access_color_attachment_read | access_color_attachment_write,
              Layout::attachment, true};
    case Usage::buffer_read:  // bound as a storage or a uniform buffer (lighting.ibl's SH)
      return {shader, access_shader_storage_read | access_uniform_read, Layout::none, false};
    case Usage::buffer_write:
      return {shader, access_shader_storage_write, Layout::none, true};
  }
  return {};
}

// Every combination worked out once: per access, the switch's jump mispredicted.
constexpr size_t usage_count = static_cast<size_t>(Usage::buffer_write) + 1;
using AccessTable = std::array<std::array<std::array<std::array<AccessInfo, 2>, 2>, 2>, usage_count>;
constexpr AccessTable access_table = [] {
  AccessTable table{};
  for (size_t u = 0; u < usage_count; ++u)
    for (int queue = 0; queue < 2; ++queue)
      for (int buffer = 0; buffer < 2; ++buffer)
        for (int depth = 0; depth < 2; ++depth)
          table[u][queue][buffer][depth] =
              describe_access(static_cast<Usage>(u), static_cast<Queue>(queue), buffer != 0, depth != 0);
  return table;
}();

}  // namespace

AccessInfo access_info(Usage usage, Queue queue, const LoweredResource& resource) {
  return access_table[static_cast<size_t>(usage)][static_cast<size_t>(queue)][resource.kind == ResourceKind::buffer]
                     [resource.depth_format];
}

CachedVector<Barrier> synchronize(const LoweredGraph& lowered, const CachedVector<int>& order,
                                  const MemoryLayout& memory) {
  const size_t count = lowered.resources.size();
  CachedVector<Group> groups;
  groups.reserve(lowered.access_count());              // each access starts at most one group: no regrowth
  CachedVector<int> head(count, -1), tail(count, -1);  // per resource: its first and last group
  std::vector<std::pair<int, AccessInfo>> uses;       // one pass's uses, one per resource
  for (int pos = 0; pos < static_cast<int>(order.size()); ++pos) {
    const LoweredPass& pass = lowered.passes[order[pos]];
    // A pass that uses a resource twice (sampled and as storage, say) needs both at once: merge
    // them before grouping, so they join a group or start one together, never one of each.
    uses.clear();
    for (const auto& a : pass.accesses) {
      AccessInfo info = access_info(a.usage, pass.queue, lowered.resources[a.resource]);
      auto same = std::find_if(uses.begin(), uses.end(), [&](const auto& u) { return u.first == a.resource; });
      if (same != uses.end())
        same->second = merge(same->second, info);
      else
        uses.emplace_back(a.resource, info);
    }
    for (const auto& [resource, info] : uses) {
      int last = tail[resource];
      if (last >= 0 && !info.writes && !groups[last].info.writes && groups[last].info.layout == info.layout) {
        groups[last].info = merge(groups[last].info, info);
        continue;
      }
      groups.push_back({pos, info});
      tail[resource] = static_cast<int>(groups.size()) - 1;
      (last >= 0 ? groups[last].next : head[resource]) = tail[resource];
    }
  }
  // A current history resource's partner (its previous-frame copy).
  CachedVector<int> previous_copy(count, -1);
  for (size_t r = 0; r < count; ++r)
    if (lowered.resources[r].history_of >= 0) previous_copy[lowered.resources[r].history_of] = static_cast<int>(r);

  CachedVector<Barrier> out;
  out.reserve(groups.size());  // at most one barrier per group
  for (size_t r = 0; r < count; ++r) {
    if (head[r] < 0) continue;
    const Group& front = groups[head[r]];
    const LoweredResource& res = lowered.resources[r];
    const bool image = res.kind != ResourceKind::buffer;

    // Before the first group: wait for whoever held these bytes last.
    Barrier first;
    first.before = front.first;
    first.resource = static_cast<int>(r);
    first.dst_stages = front.info.stages;
    first.dst_access = front.info.access;
    first.old_layout = image ? Layout::undefined : Layout::none;
    first.new_layout = front.info.layout;
    first.reason = BarrierReason::first_use;
    auto wait_for = [&](int other) {
      if (tail[other] < 0) return;
      const AccessInfo& last = groups[tail[other]].info;
      first.src_stages |= last.stages;
      first.src_access |= last.access & access_write_mask;
    };
    bool needed = image;
    if (res.history_of >= 0) {
      // Last frame this was the current half: its last access there precedes this one. Reads
      // in the same layout after reads need nothing; a write or a new layout does.
      if (int partner = tail[res.history_of]; partner >= 0) {
        const AccessInfo& last = groups[partner].info;
        wait_for(res.history_of);
        first.old_layout = last.layout;
        needed = last.writes || front.info.writes || last.layout != front.info.layout;
      }
      first.reason = BarrierReason::history;
    } else if (previous_copy[r] >= 0) {
      wait_for(previous_copy[r]);  // last frame's reads of these bytes, before this frame writes
      first.reason = BarrierReason::history;
    } else if (memory.placements[r].predecessor_count > 0) {
      for (int p : memory.predecessors_of(static_cast<int>(r))) wait_for(p);
      first.reason = BarrierReason::alias;
    }
    if (res.history_of < 0 && first.reason != BarrierReason::first_use) needed = true;
    if (needed) out.push_back(first);

    for (const Group* g = &front; g->next >= 0; g = &groups[g->next]) {
      const Group& next = groups[g->next];
      const AccessInfo& before = g->info;
      const AccessInfo& after = next.info;
      bool handoff = res.lifetime == ResourceLifetime::cached && lowered.passes[order[g->first]].is_static &&
                     !lowered.passes[order[next.first]].is_static;
      out.push_back({next.first, static_cast<int>(r), before.stages, before.access & access_write_mask, after.stages,
                     after.access, before.layout, after.layout, reason_between(before, after), handoff});
    }
  }
  return sorted_by_pass(std::move(out), order.size());
}

JsonValue dump_barriers(const LoweredGraph& lowered, const CachedVector<int>& order,
                        const CachedVector<Barrier>& barriers) {
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

}  // namespace lg
