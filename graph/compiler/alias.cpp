#include "graph/compiler/alias.h"

#include <algorithm>
#include <map>

namespace lg {
namespace {

uint64_t align_up(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

bool is_persistent(const LoweredResource& r) {
  return r.lifetime == ResourceLifetime::cached || r.lifetime == ResourceLifetime::history;
}

// Placed intervals of the schedule, for "who is alive at pass t" in O(log passes + answers):
// a segment tree whose nodes hold the intervals covering their whole range.
class StabbingTree {
 public:
  explicit StabbingTree(int passes) : size_(std::max(passes, 1)), nodes_(4 * static_cast<size_t>(size_)) {}

  void insert(int first, int last, int id) { insert(1, 0, size_, first, last + 1, id); }

  template <class F>
  void stab(int t, F&& visit) const {
    size_t node = 1;
    int lo = 0, hi = size_;
    for (;;) {
      for (int id : nodes_[node]) visit(id);
      if (hi - lo == 1) return;
      int mid = (lo + hi) / 2;
      if (t < mid) node = 2 * node, hi = mid;
      else node = 2 * node + 1, lo = mid;
    }
  }

 private:
  int size_;
  std::vector<std::vector<int>> nodes_;

  void insert(size_t node, int lo, int hi, int begin, int end, int id) {
    if (end <= lo || hi <= begin) return;
    if (begin <= lo && hi <= end) {
      nodes_[node].push_back(id);
      return;
    }
    int mid = (lo + hi) / 2;
    insert(2 * node, lo, mid, begin, end, id);
    insert(2 * node + 1, mid, hi, begin, end, id);
  }
};

// Greedy by size: the largest resources are placed first, each at the offset that leaves the
// smallest gap among the placed resources whose lifetimes overlap it: those alive when it
// starts, and those that start while it lives. Both are indexed, so a placement costs about
// the size of the live set, not the number of resources.
class GreedyPlacer {
 public:
  GreedyPlacer(int passes, size_t resources) : alive_(passes), seen_(resources, 0) {}

  uint64_t place(int r, Lifetime life, uint64_t bytes, uint64_t alignment, std::vector<Placement>& placements) {
    ++stamp_;
    conflicts_.clear();
    auto note = [&](int other) {
      if (seen_[other] == stamp_) return;
      seen_[other] = stamp_;
      conflicts_.push_back({placements[other].offset, placements[other].offset + placements[other].size});
    };
    alive_.stab(life.first, note);
    for (auto it = starts_.upper_bound(life.first); it != starts_.end() && it->first <= life.last; ++it) note(it->second);
    std::sort(conflicts_.begin(), conflicts_.end());

    uint64_t best = UINT64_MAX, best_gap = UINT64_MAX, cursor = 0;
    for (const auto& [start, end] : conflicts_) {
      uint64_t offset = align_up(cursor, alignment);
      if (offset + bytes <= start && start - cursor < best_gap) best = offset, best_gap = start - cursor;
      cursor = std::max(cursor, end);
    }
    if (best == UINT64_MAX) best = align_up(cursor, alignment);
    alive_.insert(life.first, life.last, r);
    starts_.emplace(life.first, r);
    size_ = std::max(size_, best + bytes);
    return best;
  }

  uint64_t size() const { return size_; }

 private:
  StabbingTree alive_;
  std::multimap<int, int> starts_;  // first pass -> resource
  std::vector<uint32_t> seen_;
  uint32_t stamp_ = 0;
  std::vector<std::pair<uint64_t, uint64_t>> conflicts_;
  uint64_t size_ = 0;
};

// Which resource last held each byte range, visited in order of first use: a resource's
// predecessors are the last holders of its bytes (they ended before it began, or they would
// have conflicted).
class LastOwners {
 public:
  void take(uint64_t start, uint64_t end, int owner, std::vector<int>& predecessors) {
    auto it = owners_.upper_bound(start);
    if (it != owners_.begin() && std::prev(it)->second.first > start) --it;
    while (it != owners_.end() && it->first < end) {
      auto [s, value] = *it;
      auto [e, previous] = value;
      predecessors.push_back(previous);
      it = owners_.erase(it);
      if (s < start) owners_.emplace(s, std::pair{start, previous});
      if (e > end) it = owners_.emplace(end, std::pair{e, previous}).first;
    }
    owners_.emplace(start, std::pair{end, owner});
    std::sort(predecessors.begin(), predecessors.end());
    predecessors.erase(std::unique(predecessors.begin(), predecessors.end()), predecessors.end());
  }

 private:
  std::map<uint64_t, std::pair<uint64_t, int>> owners_;  // start -> (end, owner)
};

}  // namespace

MemoryLayout alias(const LoweredGraph& lowered, const std::vector<Lifetime>& lifetimes, const AliasOptions& options) {
  const size_t count = lowered.resources.size();
  MemoryLayout out;
  out.blocks = {{0, options.enabled}, {0, false}};
  out.placements.resize(count);
  auto alignment = [&](const LoweredResource& r) {
    return r.kind == ResourceKind::buffer ? options.buffer_alignment : options.image_alignment;
  };

  // Persistent resources, and everything when aliasing is off: one after another.
  std::vector<int> shared;
  int passes = 0;
  for (size_t r = 0; r < count; ++r) {
    const LoweredResource& res = lowered.resources[r];
    if (!lifetimes[r].used()) continue;
    passes = std::max(passes, lifetimes[r].last + 1);
    Placement& p = out.placements[r];
    p.size = res.bytes;
    p.block = is_persistent(res) ? 1 : 0;
    if (p.block == 0 && options.enabled) {
      shared.push_back(static_cast<int>(r));
      continue;
    }
    MemoryBlock& block = out.blocks[p.block];
    p.offset = align_up(block.size, alignment(res));
    block.size = p.offset + res.bytes;
  }
  if (!options.enabled) return out;

  std::sort(shared.begin(), shared.end(), [&](int a, int b) {
    uint64_t sa = lowered.resources[a].bytes, sb = lowered.resources[b].bytes;
    if (sa != sb) return sa > sb;
    return lifetimes[a].first != lifetimes[b].first ? lifetimes[a].first < lifetimes[b].first : a < b;
  });
  GreedyPlacer placer(passes, count);
  for (int r : shared)
    out.placements[r].offset = placer.place(r, lifetimes[r], out.placements[r].size, alignment(lowered.resources[r]), out.placements);
  out.blocks[0].size = placer.size();

  std::sort(shared.begin(), shared.end(), [&](int a, int b) {
    return lifetimes[a].first != lifetimes[b].first ? lifetimes[a].first < lifetimes[b].first : a < b;
  });
  LastOwners owners;
  for (int r : shared) {
    Placement& p = out.placements[r];
    owners.take(p.offset, p.offset + p.size, r, p.predecessors);
  }
  return out;
}

JsonValue dump_memory(const LoweredGraph& lowered, const MemoryLayout& memory) {
  JsonValue out = JsonValue::object();
  JsonValue& blocks = out.set("blocks", JsonValue::array());
  for (const auto& b : memory.blocks) {
    JsonValue& block = blocks.push(JsonValue::object());
    block.set("bytes", b.size);
    block.set("aliased", b.aliased);
  }
  JsonValue& placements = out.set("placements", JsonValue::array());
  for (size_t r = 0; r < memory.placements.size(); ++r) {
    const Placement& p = memory.placements[r];
    JsonValue& place = placements.push(JsonValue::object());
    place.set("resource", lowered.resources[r].name);
    place.set("block", p.block);
    place.set("offset", p.offset);
    place.set("bytes", p.size);
    if (!p.predecessors.empty()) {
      JsonValue& preds = place.set("takes_over_from", JsonValue::array());
      for (int q : p.predecessors) preds.push(lowered.resources[q].name);
    }
  }
  return out;
}

}  // namespace lg
