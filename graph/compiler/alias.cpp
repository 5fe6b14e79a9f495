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
  // `by_first`: the resources to place, sorted by first use. Internally a resource is its
  // position in that order, so the scan below reads placed spans from one contiguous array.
  GreedyPlacer(int passes, const std::vector<int>& by_first, const std::vector<Lifetime>& lives)
      : alive_(passes), position_(lives.size(), -1), spans_(by_first.size()), placed_(by_first.size(), 0) {
    firsts_.reserve(by_first.size());
    for (size_t k = 0; k < by_first.size(); ++k) {
      position_[by_first[k]] = static_cast<int>(k);
      firsts_.push_back(lives[by_first[k]].first);
    }
  }

  uint64_t place(int r, Lifetime life, uint64_t bytes, uint64_t alignment) {
    // The two sources are disjoint (first use at or before this one's, or after it) and the
    // tree holds each interval once on any root path, so nothing is counted twice.
    conflicts_.clear();
    alive_.stab(life.first, [&](int k) { conflicts_.push_back(spans_[k]); });
    for (auto k = std::upper_bound(firsts_.begin(), firsts_.end(), life.first) - firsts_.begin();
         k < static_cast<long>(firsts_.size()) && firsts_[k] <= life.last; ++k)
      if (placed_[k]) conflicts_.push_back(spans_[k]);
    sort_by_start(conflicts_);

    uint64_t best = UINT64_MAX, best_gap = UINT64_MAX, cursor = 0;
    for (const auto& [start, end] : conflicts_) {
      uint64_t offset = align_up(cursor, alignment);
      if (offset + bytes <= start && start - cursor < best_gap) best = offset, best_gap = start - cursor;
      cursor = std::max(cursor, end);
    }
    if (best == UINT64_MAX) best = align_up(cursor, alignment);
    const int k = position_[r];
    alive_.insert(life.first, life.last, k);
    spans_[k] = {best, best + bytes};
    placed_[k] = 1;
    size_ = std::max(size_, best + bytes);
    return best;
  }

  uint64_t size() const { return size_; }

 private:
  struct Span {
    uint64_t start, end;
  };

  // The gap scan does not care how equal starts are ordered. The lists are usually a dozen or
  // two long, where insertion sort beats std::sort.
  static void sort_by_start(std::vector<Span>& spans) {
    if (spans.size() > 32) {
      std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.start < b.start; });
      return;
    }
    for (size_t i = 1; i < spans.size(); ++i) {
      Span s = spans[i];
      size_t j = i;
      for (; j > 0 && spans[j - 1].start > s.start; --j) spans[j] = spans[j - 1];
      spans[j] = s;
    }
  }

  StabbingTree alive_;          // holds positions
  std::vector<int> position_;   // resource -> position in first-use order
  std::vector<int> firsts_;     // by position: first use
  std::vector<Span> spans_;     // by position: bytes, once placed
  std::vector<char> placed_;    // by position
  std::vector<Span> conflicts_;
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
  // By first use, ties by index: the order the placer scans and the order bytes change hands.
  std::vector<std::pair<int, int>> firsts;
  firsts.reserve(shared.size());
  for (int r : shared) firsts.emplace_back(lifetimes[r].first, r);
  std::sort(firsts.begin(), firsts.end());
  std::vector<int> by_first;
  by_first.reserve(shared.size());
  for (const auto& [first, r] : firsts) by_first.push_back(r);

  GreedyPlacer placer(passes, by_first, lifetimes);
  for (const Key& key : keys) {
    Placement& p = out.placements[key.index];
    p.offset = placer.place(key.index, lifetimes[key.index], p.size, needs[key.index].alignment);
  }
  out.blocks[0].size = placer.size();
  if (out.blocks[0].size > stacked) {
    // Packing by size lost to plain stacking on alignment padding (little overlaps in time):
    // stack them in resource order, as with aliasing off.
    uint64_t end = 0;
    for (int r : shared) {
      out.placements[r].offset = align_up(end, needs[r].alignment);
      end = out.placements[r].offset + out.placements[r].size;
    }
    out.blocks[0].size = end;
  }

  LastOwners owners(shared.size());
  for (int r : by_first) {
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
