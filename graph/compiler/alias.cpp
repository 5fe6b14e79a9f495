#include "graph/compiler/alias.h"

#include <algorithm>
#include <bit>
#include <numeric>
#include <utility>

namespace lg {
namespace {

uint64_t align_up(uint64_t v, uint64_t a) {
  if ((a & (a - 1)) == 0) return a == 0 ? v : (v + a - 1) & ~(a - 1);  // powers of two: no division
  return (v + a - 1) / a * a;
}

bool is_persistent(const LoweredResource& r) {
  return r.lifetime == ResourceLifetime::cached || r.lifetime == ResourceLifetime::history;
}

// A resource's bytes within its block: [start, end).
struct ByteRange {
  uint64_t start, end;
  uint32_t start_id;  // the placer's number for `start`: equal starts, equal numbers
};

// The distinct offsets placements start at, each with a number for good (in order of first
// sight) and its rank among them. Greedy placement reuses offsets (a few hundred at 10,000
// nodes), so ranks turn sorting ranges by start into setting bits in a small bitmap.
class StartOffsets {
 public:
  // Offset 0 is known from the start (the first placement lands there), so every range,
  // placed or not, has a start number to mark with.
  explicit StartOffsets(size_t resources) : known_(64) {
    sorted_.reserve(resources);
    id_of_rank_.reserve(resources);
    rank_of_id_.reserve(resources);
    furthest_.reserve(resources);
    add(0);
  }

  // The number of `offset`, which becomes a known start if it is not one yet. Most offsets
  // are known: they are found in a hash table, without a binary search's mispredicted steps.
  // A new start shifts the ranks above it: O(starts), a few hundred steps a few hundred times
  // (quadratic in the resources only if nearly every one starts at an offset of its own).
  uint32_t add(uint64_t offset) {
    Known& k = slot_of(offset);
    if (k.id >= 0) return static_cast<uint32_t>(k.id);
    const auto at = std::lower_bound(sorted_.begin(), sorted_.end(), offset);
    const auto rank = static_cast<uint32_t>(at - sorted_.begin());
    const auto id = static_cast<uint32_t>(rank_of_id_.size());
    k = {offset, static_cast<int64_t>(id)};
    if (2 * (id + 1) > known_.size()) grow();
    for (uint32_t& r : rank_of_id_) r += r >= rank;
    rank_of_id_.push_back(rank);
    sorted_.insert(at, offset);
    id_of_rank_.insert(id_of_rank_.begin() + rank, id);
    furthest_.push_back(0);
    present_.resize((sorted_.size() + 63) / 64);
    return id;
  }

  // Ranges of known starts are marked one by one, then collected sorted by start, one range
  // per start ending at the furthest end of the ranges that share it. That is all the placer's
  // gap scan needs: it does not care how equal starts are ordered, and sees ranges that share
  // a start as one ending at the furthest end. Linear, with no comparisons to mispredict.
  // `keep` is 1 or 0: a range is marked or not without a branch, which would follow no pattern.
  void mark(const ByteRange& r, uint64_t keep = 1) {
    const uint64_t mask = 0 - keep;
    const uint32_t rank = rank_of_id_[r.start_id];
    furthest_[rank] = std::max(furthest_[rank], r.end & mask);
    present_[rank / 64] |= (uint64_t{1} << (rank % 64)) & mask;
  }

  // Writes the marked ranges to `out` and clears the marks; returns the new end.
  ByteRange* collect(ByteRange* out) {
    for (size_t w = 0; w < present_.size(); ++w)
      for (uint64_t bits = std::exchange(present_[w], 0); bits != 0; bits &= bits - 1) {
        const auto rank = static_cast<uint32_t>(64 * w + std::countr_zero(bits));
        *out++ = {sorted_[rank], std::exchange(furthest_[rank], 0), id_of_rank_[rank]};
      }
    return out;
  }

 private:
  struct Known {
    uint64_t offset = 0;
    int64_t id = -1;  // -1: an empty slot
  };
  CachedVector<Known> known_;  // offset -> id, open addressing, never more than half full

  // The slot holding `offset`, or the empty one where it would go.
  Known& slot_of(uint64_t offset) {
    const size_t mask = known_.size() - 1;
    size_t slot = (offset * 0x9e3779b97f4a7c15ull) >> 32 & mask;
    while (known_[slot].id >= 0 && known_[slot].offset != offset) slot = (slot + 1) & mask;
    return known_[slot];
  }

  // Twice the slots: few offsets are distinct, so the table starts small and stays in cache.
  void grow() {
    CachedVector<Known> old(2 * known_.size());
    old.swap(known_);
    for (const Known& k : old)
      if (k.id >= 0) slot_of(k.offset) = k;
  }
  CachedVector<uint64_t> sorted_;  // by rank: the offset
  CachedVector<uint32_t> id_of_rank_, rank_of_id_;
  CachedVector<uint64_t> present_;   // by rank, a bit: marked since the last collect()
  CachedVector<uint64_t> furthest_;  // by rank: the furthest end in that list; 0 when unmarked
};

// Placed intervals of the schedule, for "who is alive at pass t" in O(log passes + answers):
// a bottom-up segment tree whose nodes hold the placed intervals that cover their whole
// range; the answer is the intervals on the path from leaf t to the root. Every interval is
// known before any is placed, so each node's room is counted up front and all entries sit in
// one array, node after node: a stab reads a few contiguous runs. An entry is the interval's
// number (4 bytes), not its byte range: an interval sits in a dozen nodes.
class StabbingTree {
 public:
  StabbingTree(int passes, const CachedVector<Lifetime>& intervals)
      : leaves_(std::max(passes, 1)), start_(2 * static_cast<size_t>(leaves_) + 2, 0) {
    // Nodes 1 to 2 leaves - 1, and node 2 leaves, which an interval's right edge visits
    // without covering.
    for (const Lifetime& life : intervals) for_nodes(life, [&](int node, int covers) { start_[node + 1] += covers; });
    for (size_t node = 1; node < start_.size(); ++node) start_[node] += start_[node - 1];
    fill_.assign(start_.begin(), start_.end() - 1);
    entries_.resize(start_.back() + 1);  // the last slot takes the writes of nodes that do not cover
  }

  void insert(Lifetime life, int interval) {
    const int scratch = static_cast<int>(entries_.size()) - 1;
    for_nodes(life, [&](int node, int covers) {
      entries_[scratch + ((fill_[node] - scratch) & -covers)] = interval;  // a select the compiler keeps branch-free
      fill_[node] += covers;
    });
  }

  // Calls visit(interval) for each interval alive at pass t.
  template <class F>
  void stab(int t, F&& visit) const {
    for (int node = t + leaves_; node > 0; node /= 2)
      for (int k = start_[node]; k < fill_[node]; ++k) visit(entries_[k]);
  }

 private:
  int leaves_;
  CachedVector<int> start_;  // node -> its first slot in entries_; start_[node + 1] ends it
  CachedVector<int> fill_;   // node -> its next free slot
  CachedVector<int> entries_;

  // Visits the nodes on both edges of [first, last], each with 1 if it is one of the nodes
  // that together cover the interval exactly, else 0: whether a node covers follows no
  // pattern, so the callers add and select by it instead of branching.
  template <class F>
  void for_nodes(Lifetime life, F&& visit) const {
    for (int lo = life.first + leaves_, hi = life.last + 1 + leaves_; lo < hi; lo /= 2, hi /= 2) {
      const int lo_covers = lo & 1, hi_covers = hi & 1;
      visit(lo, lo_covers);
      lo += lo_covers;
      hi -= hi_covers;
      visit(hi, hi_covers);
    }
  }
};

// Greedy by size: the largest resources are placed first, each at the offset that leaves the
// smallest gap among the placed resources whose lifetimes overlap it: those alive when it
// starts (the stabbing tree), and those that start while it lives (a scan of the resources
// sorted by first use). A placement costs about the size of the live set.
class GreedyPlacer {
 public:
  // `by_first`: the resources to place, sorted by first use. Internally a resource is its
  // position in that order, so the scan below reads placed ranges from one contiguous array.
  GreedyPlacer(int passes, const CachedVector<int>& by_first, const CachedVector<Lifetime>& lives)
      : alive_(passes, lifetimes_of(by_first, lives)),
        position_(lives.size(), -1),
        ranges_(by_first.size()),
        placed_(by_first.size(), 0),
        conflicts_(by_first.size()),
        starts_(by_first.size()) {
    begin_after_.assign(static_cast<size_t>(std::max(passes, 1)), 0);
    for (size_t k = 0; k < by_first.size(); ++k) {
      position_[by_first[k]] = static_cast<int>(k);
      ++begin_after_[lives[by_first[k]].first];
    }
    std::partial_sum(begin_after_.begin(), begin_after_.end(), begin_after_.begin());
  }

  uint64_t place(int r, Lifetime life, uint64_t bytes, uint64_t alignment) {
    // The two sources are disjoint (first use at or before this one's, or after it) and the
    // tree holds each interval once on any root path, so nothing is counted twice: the
    // conflicts are distinct placed resources, fewer than all of them.
    alive_.stab(life.first, [&](int position) { starts_.mark(ranges_[position]); });
    for (int k = begin_after_[life.first]; k < begin_after_[life.last]; ++k) starts_.mark(ranges_[k], placed_[k]);
    const ByteRange* end = starts_.collect(conflicts_.data());

    uint64_t best = UINT64_MAX, best_gap = UINT64_MAX, cursor = 0;
    for (const ByteRange* c = conflicts_.data(); c != end; ++c) {
      uint64_t offset = align_up(cursor, alignment), gap = c->start - cursor;
      bool better = offset + bytes <= c->start && gap < best_gap;
      best = better ? offset : best;
      best_gap = better ? gap : best_gap;
      cursor = std::max(cursor, c->end);
    }
    if (best == UINT64_MAX) best = align_up(cursor, alignment);
    const int k = position_[r];
    ranges_[k] = {best, best + bytes, starts_.add(best)};
    placed_[k] = 1;
    alive_.insert(life, k);
    size_ = std::max(size_, best + bytes);
    return best;
  }

  uint64_t size() const { return size_; }

 private:
  static CachedVector<Lifetime> lifetimes_of(const CachedVector<int>& resources, const CachedVector<Lifetime>& lives) {
    CachedVector<Lifetime> out;
    out.reserve(resources.size());
    for (int r : resources) out.push_back(lives[r]);
    return out;
  }

  StabbingTree alive_;                // holds placed positions
  CachedVector<int> position_;        // resource -> position in first-use order
  CachedVector<int> begin_after_;     // pass -> the first position whose first use is later
  CachedVector<ByteRange> ranges_;    // by position: bytes, once placed
  CachedVector<uint8_t> placed_;      // by position: 1 once placed
  CachedVector<ByteRange> conflicts_;  // room for every placed resource
  StartOffsets starts_;               // of placed ranges
  uint64_t size_ = 0;
};

// Which resource last held each byte range, visited in order of first use: a resource's
// predecessors are the last holders of its bytes (they ended before it began, or they would
// have conflicted).
class LastOwners {
 public:
  // Each take() adds at most two pieces: room for all of them up front.
  explicit LastOwners(size_t takes) { owned_.reserve(2 * takes + 1); }

  // Gives `owner` the bytes [start, end) and appends their last owners to `list`, each once;
  // returns how many it appended.
  uint32_t take(uint64_t start, uint64_t end, int owner, CachedVector<int>& list) {
    // Disjoint and sorted by start, so sorted by end too.
    auto first = std::partition_point(owned_.begin(), owned_.end(), [&](const Owned& o) { return o.end <= start; });
    auto last = first;
    found_.clear();
    for (; last != owned_.end() && last->start < end; ++last) found_.push_back(last->owner);
    // What replaces [first, last): the part of the first one before `start`, the new owner,
    // and the part of the last one after `end`.
    Owned pieces[3];
    int count = 0;
    if (first != last && first->start < start) pieces[count++] = {first->start, start, first->owner};
    pieces[count++] = {start, end, owner};
    if (first != last && (last - 1)->end > end) pieces[count++] = {end, (last - 1)->end, (last - 1)->owner};
    const auto at = first - owned_.begin(), removed = last - first;
    if (count > removed)
      owned_.insert(owned_.begin() + at + removed, count - removed, Owned{});
    else
      owned_.erase(owned_.begin() + at + count, owned_.begin() + at + removed);
    std::copy(pieces, pieces + count, owned_.begin() + at);
    std::sort(found_.begin(), found_.end());
    const auto unique_end = std::unique(found_.begin(), found_.end());
    list.insert(list.end(), found_.begin(), unique_end);
    return static_cast<uint32_t>(unique_end - found_.begin());
  }

 private:
  struct Owned {
    uint64_t start = 0, end = 0;
    int owner = -1;
  };
  CachedVector<Owned> owned_;  // by start
  std::vector<int> found_;    // the owners one take() replaces
};

// The placing order, largest first, ties by first use, then index: `by_first` bucketed by size,
// stably. Resources come in few sizes (frame-sized images of a handful of formats), so a hash
// of the sizes and a counting sort over the distinct ones replace a comparison sort, whose
// three-way key mispredicted on every other comparison.
CachedVector<int> largest_first(const CachedVector<int>& by_first, const CachedVector<ResourceMemory>& needs) {
  const size_t mask = std::bit_ceil(2 * by_first.size() + 1) - 1;
  CachedVector<int> slot_size(mask + 1, -1);  // open addressing: index into `sizes`, or -1
  std::vector<uint64_t> sizes;                // distinct, in order of first sight
  CachedVector<int> size_of(by_first.size());  // by position in by_first: index into `sizes`
  for (size_t k = 0; k < by_first.size(); ++k) {
    const uint64_t bytes = needs[by_first[k]].bytes;
    size_t s = (bytes * 0x9e3779b97f4a7c15ull) >> 32 & mask;
    while (slot_size[s] >= 0 && sizes[slot_size[s]] != bytes) s = (s + 1) & mask;
    if (slot_size[s] < 0) {
      slot_size[s] = static_cast<int>(sizes.size());
      sizes.push_back(bytes);
    }
    size_of[k] = slot_size[s];
  }
  // Buckets numbered largest size first; then a counting sort, stable within each.
  std::vector<int> largest(sizes.size()), bucket(sizes.size());
  std::iota(largest.begin(), largest.end(), 0);
  std::sort(largest.begin(), largest.end(), [&](int a, int b) { return sizes[a] > sizes[b]; });
  for (size_t b = 0; b < largest.size(); ++b) bucket[largest[b]] = static_cast<int>(b);
  std::vector<int> start(sizes.size() + 1, 0);
  for (int& d : size_of) ++start[(d = bucket[d]) + 1];
  for (size_t b = 0; b < sizes.size(); ++b) start[b + 1] += start[b];
  CachedVector<int> out(by_first.size());
  for (size_t k = 0; k < by_first.size(); ++k) out[start[size_of[k]]++] = by_first[k];
  return out;
}

}  // namespace

MemoryLayout alias(const LoweredGraph& lowered, const CachedVector<Lifetime>& lifetimes, const AliasOptions& options) {
  const size_t count = lowered.resources.size();
  MemoryLayout out;
  out.blocks = {{0, options.enabled}, {0, false}};
  out.placements.resize(count);
  CachedVector<ResourceMemory> needs(count);
  for (size_t r = 0; r < count; ++r) {
    const LoweredResource& res = lowered.resources[r];
    if (!lifetimes[r].used()) continue;
    if (options.memory)
      needs[r] = options.memory(res);
    else
      needs[r] = {res.bytes, res.kind == ResourceKind::buffer ? options.buffer_alignment : options.image_alignment};
  }

  // Persistent resources, and everything when aliasing is off: one after another.
  CachedVector<int> shared;
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

  // By first use, ties by index: the order the placer scans and the order bytes change hands.
  // A counting sort over schedule positions (`shared` is in index order, and it is stable).
  CachedVector<int> start(static_cast<size_t>(passes) + 1, 0), by_first(shared.size());
  for (int r : shared) ++start[lifetimes[r].first + 1];
  for (int p = 0; p < passes; ++p) start[p + 1] += start[p];
  for (int r : shared) by_first[start[lifetimes[r].first]++] = r;

  GreedyPlacer placer(passes, by_first, lifetimes);
  for (int r : largest_first(by_first, needs)) {
    Placement& p = out.placements[r];
    p.offset = placer.place(r, lifetimes[r], p.size, needs[r].alignment);
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

  LastOwners owners(by_first.size());
  out.predecessors.reserve(2 * by_first.size());  // rarely more than two each: no regrowth
  for (int r : by_first) {
    Placement& p = out.placements[r];
    p.first_predecessor = static_cast<uint32_t>(out.predecessors.size());
    p.predecessor_count = owners.take(p.offset, p.offset + p.size, r, out.predecessors);
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
    if (p.predecessor_count > 0) {
      JsonValue& preds = place.set("takes_over_from", JsonValue::array());
      for (int q : memory.predecessors_of(static_cast<int>(r))) preds.push(lowered.resources[q].name);
    }
  }
  return out;
}

}  // namespace lg
