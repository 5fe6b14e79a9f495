#include "graph/compiler/alias.h"

#include <algorithm>
#include <map>
#include <memory_resource>

namespace lg {
namespace {

uint64_t align_up(uint64_t v, uint64_t a) {
  if ((a & (a - 1)) == 0) return a == 0 ? v : (v + a - 1) & ~(a - 1);  // powers of two: no division
  return (v + a - 1) / a * a;
}

bool is_persistent(const LoweredResource& r) {
  return r.lifetime == ResourceLifetime::cached || r.lifetime == ResourceLifetime::history;
}

// Placed intervals of the schedule, for "who is alive at pass t" in O(log passes + answers):
// a bottom-up segment tree whose nodes hold, as linked lists in one pool, the intervals that
// cover their whole range; the answer is the lists on the path from leaf t to the root.
class StabbingTree {
 public:
  explicit StabbingTree(int passes) : leaves_(std::max(passes, 1)), head_(2 * static_cast<size_t>(leaves_), -1) {}

  void insert(int first, int last, int id) {
    for (int lo = first + leaves_, hi = last + 1 + leaves_; lo < hi; lo /= 2, hi /= 2) {
      if (lo & 1) link(lo++, id);
      if (hi & 1) link(--hi, id);
    }
  }

  template <class F>
  void stab(int t, F&& visit) const {
    for (int node = t + leaves_; node > 0; node /= 2)
      for (int e = head_[node]; e >= 0; e = pool_[e].next) visit(pool_[e].id);
  }

 private:
  struct Entry {
    int id, next;
  };
  int leaves_;
  std::vector<int> head_;
  std::vector<Entry> pool_;

  void link(int node, int id) {
    pool_.push_back({id, head_[node]});
    head_[node] = static_cast<int>(pool_.size()) - 1;
  }
};

// Greedy by size: the largest resources are placed first, each at the offset that leaves the
// smallest gap among the placed resources whose lifetimes overlap it: those alive when it
// starts (the stabbing tree), and those that start while it lives (a scan of the resources
// sorted by first use). A placement costs about the size of the live set.
class GreedyPlacer {
 public:
  GreedyPlacer(int passes, const std::vector<int>& resources, const std::vector<Lifetime>& lives)
      : alive_(passes), by_first_(resources), placed_(lives.size(), 0) {
    std::sort(by_first_.begin(), by_first_.end(), [&](int a, int b) { return lives[a].first < lives[b].first; });
    for (int r : by_first_) firsts_.push_back(lives[r].first);
  }

  uint64_t place(int r, Lifetime life, uint64_t bytes, uint64_t alignment, std::vector<Placement>& placements) {
    // The two sources are disjoint (first use at or before this one's, or after it) and the
    // tree holds each interval once on any root path, so nothing is counted twice.
    conflicts_.clear();
    auto note = [&](int other) {
      conflicts_.push_back({placements[other].offset, placements[other].offset + placements[other].size});
    };
    alive_.stab(life.first, note);
    auto begin = std::upper_bound(firsts_.begin(), firsts_.end(), life.first) - firsts_.begin();
    for (auto k = begin; k < static_cast<long>(firsts_.size()) && firsts_[k] <= life.last; ++k)
      if (placed_[by_first_[k]]) note(by_first_[k]);
    std::sort(conflicts_.begin(), conflicts_.end());

    uint64_t best = UINT64_MAX, best_gap = UINT64_MAX, cursor = 0;
    for (const auto& [start, end] : conflicts_) {
      uint64_t offset = align_up(cursor, alignment);
      if (offset + bytes <= start && start - cursor < best_gap) best = offset, best_gap = start - cursor;
      cursor = std::max(cursor, end);
    }
    if (best == UINT64_MAX) best = align_up(cursor, alignment);
    alive_.insert(life.first, life.last, r);
    placed_[r] = 1;
    size_ = std::max(size_, best + bytes);
    return best;
  }

  uint64_t size() const { return size_; }

 private:
  StabbingTree alive_;
  std::vector<int> by_first_, firsts_;  // resources to place, sorted by first use
  std::vector<char> placed_;
  std::vector<std::pair<uint64_t, uint64_t>> conflicts_;
  uint64_t size_ = 0;
};

// Which resource last held each byte range, visited in order of first use: a resource's
// predecessors are the last holders of its bytes (they ended before it began, or they would
// have conflicted).
class LastOwners {
 public:
  explicit LastOwners(size_t resources) : pool_(resources * 3 * sizeof(std::pair<const uint64_t, std::pair<uint64_t, int>>) + 4096), owners_(&pool_) {}

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
  // Nodes come from one arena: the map is rebuilt for every plan and dropped whole.
  std::pmr::monotonic_buffer_resource pool_;
  std::pmr::map<uint64_t, std::pair<uint64_t, int>> owners_;  // start -> (end, owner)
};

}  // namespace

MemoryLayout alias(const LoweredGraph& lowered, const std::vector<Lifetime>& lifetimes, const AliasOptions& options) {
  const size_t count = lowered.resources.size();
  MemoryLayout out;
  out.blocks = {{0, options.enabled}, {0, false}};
  out.placements.resize(count);
  std::vector<ResourceMemory> needs(count);
  for (size_t r = 0; r < count; ++r) {
    const LoweredResource& res = lowered.resources[r];
    if (!lifetimes[r].used()) continue;
    if (options.memory) needs[r] = options.memory(res);
    else needs[r] = {res.bytes, res.kind == ResourceKind::buffer ? options.buffer_alignment : options.image_alignment};
  }

  // Persistent resources, and everything when aliasing is off: one after another.
  std::vector<int> shared;
  int passes = 0;
  for (size_t r = 0; r < count; ++r) {
    const LoweredResource& res = lowered.resources[r];
    if (!lifetimes[r].used()) continue;
    passes = std::max(passes, lifetimes[r].last + 1);
    Placement& p = out.placements[r];
    p.size = needs[r].bytes;
    p.block = is_persistent(res) ? 1 : 0;
    if (p.block == 0 && options.enabled) {
      shared.push_back(static_cast<int>(r));
      continue;
    }
    MemoryBlock& block = out.blocks[p.block];
    p.offset = align_up(block.size, needs[r].alignment);
    block.size = p.offset + p.size;
  }
  if (!options.enabled) return out;
  uint64_t stacked = 0;  // block 0's size with aliasing off: what aliasing must never exceed
  for (int r : shared) stacked = align_up(stacked, needs[r].alignment) + needs[r].bytes;

  // Largest first; sorting compact keys rather than whole resources keeps the caches warm.
  struct Key {
    uint64_t bytes;
    int first, index;
  };
  std::vector<Key> keys;
  keys.reserve(shared.size());
  for (int r : shared) keys.push_back({needs[r].bytes, lifetimes[r].first, r});
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    if (a.bytes != b.bytes) return a.bytes > b.bytes;
    return a.first != b.first ? a.first < b.first : a.index < b.index;
  });
  for (size_t k = 0; k < keys.size(); ++k) shared[k] = keys[k].index;
  GreedyPlacer placer(passes, shared, lifetimes);
  for (int r : shared)
    out.placements[r].offset = placer.place(r, lifetimes[r], out.placements[r].size, needs[r].alignment, out.placements);
  out.blocks[0].size = placer.size();
  if (out.blocks[0].size > stacked) {
    // Packing by size lost to plain stacking on alignment padding (little overlaps in time):
    // stack them in resource order, as with aliasing off.
    std::sort(shared.begin(), shared.end());
    uint64_t end = 0;
    for (int r : shared) {
      out.placements[r].offset = align_up(end, needs[r].alignment);
      end = out.placements[r].offset + out.placements[r].size;
    }
    out.blocks[0].size = end;
  }

  std::sort(shared.begin(), shared.end(), [&](int a, int b) {
    return lifetimes[a].first != lifetimes[b].first ? lifetimes[a].first < lifetimes[b].first : a < b;
  });
  LastOwners owners(shared.size());
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
