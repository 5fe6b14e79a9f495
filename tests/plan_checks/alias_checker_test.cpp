// An independent check of the alias phase over many random graphs: no two resources alive at
// the same time share a byte, everything fits its block and its alignment, persistent resources
// never share, and the recorded predecessors are exactly the last earlier holders of the bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tests/plan_checks/plan_fixtures.h"

namespace lg::test {
namespace {

bool persistent(const PlanResource& r) {
  return r.desc.lifetime == ResourceLifetime::cached || r.desc.lifetime == ResourceLifetime::history;
}

// Returns a description of the first violation, or empty.
std::string check_memory(const Plan& plan, const AliasOptions& options) {
  const auto& res = plan.resources;
  uint64_t transient_sum = 0, aligned_sum = 0;
  for (size_t a = 0; a < res.size(); ++a) {
    const PlanResource& r = res[a];
    if (r.first < 0) continue;
    const Placement& p = r.placement;
    if (p.block != (persistent(r) ? 1 : 0)) return r.desc.name + " is in the wrong block";
    if (p.size != r.desc.bytes) return r.desc.name + " reserves a different size";
    if (p.offset + p.size > plan.blocks[p.block].size) return r.desc.name + " does not fit its block";
    uint64_t alignment = r.desc.kind == ResourceKind::buffer ? options.buffer_alignment : options.image_alignment;
    if (p.offset % alignment != 0) return r.desc.name + " is misaligned";
    if (!persistent(r)) transient_sum += r.desc.bytes, aligned_sum += r.desc.bytes + alignment - 1;
    for (size_t b = a + 1; b < res.size(); ++b) {
      const PlanResource& s = res[b];
      if (s.first < 0 || s.placement.block != p.block) continue;
      bool bytes_overlap = p.offset < s.placement.offset + s.placement.size && s.placement.offset < p.offset + p.size;
      bool time_overlap = r.first <= s.last && s.first <= r.last;
      if (bytes_overlap && (time_overlap || p.block == 1 || !options.enabled))
        return r.desc.name + " and " + s.desc.name + " share bytes";
    }
  }
  // Sharing never costs more than laying every resource out one after another; alignment
  // padding is the only thing that can make the block exceed the plain sum of sizes.
  if (plan.memory.transient > aligned_sum) return "aliasing made it bigger";
  if (plan.memory.transient_unaliased != transient_sum) return "the unaliased total is not the sum of the sizes";

  // Predecessors by brute force: for each byte range of a resource, the resource that held it
  // last before this one started (every holder of a byte ended before the next began).
  for (size_t b = 0; b < res.size(); ++b) {
    const PlanResource& r = res[b];
    if (r.first < 0 || persistent(r)) continue;
    std::set<int> expected;
    // Cut the resource's bytes at every boundary of an earlier overlapping holder.
    std::vector<uint64_t> cuts = {r.placement.offset, r.placement.offset + r.placement.size};
    std::vector<size_t> earlier;
    for (size_t a = 0; a < res.size(); ++a) {
      const PlanResource& s = res[a];
      if (a == b || s.first < 0 || persistent(s)) continue;
      bool before = s.first < r.first || (s.first == r.first && a < b);
      bool overlap = s.placement.offset < r.placement.offset + r.placement.size &&
                     r.placement.offset < s.placement.offset + s.placement.size;
      if (!before || !overlap) continue;
      earlier.push_back(a);
      cuts.push_back(std::clamp(s.placement.offset, r.placement.offset, r.placement.offset + r.placement.size));
      cuts.push_back(std::clamp(s.placement.offset + s.placement.size, r.placement.offset, r.placement.offset + r.placement.size));
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
      if (cuts[k] == cuts[k + 1]) continue;
      uint64_t byte = cuts[k];
      int last = -1;
      for (size_t a : earlier) {
        const PlanResource& s = res[a];
        if (byte < s.placement.offset || byte >= s.placement.offset + s.placement.size) continue;
        if (last < 0 || s.first > res[last].first || (s.first == res[last].first && static_cast<int>(a) > last)) last = static_cast<int>(a);
      }
      if (last >= 0) expected.insert(last);
    }
    std::set<int> actual(r.placement.predecessors.begin(), r.placement.predecessors.end());
    if (actual != expected) return r.desc.name + " has the wrong predecessors";
  }
  return {};
}

TEST(PlanAliasChecker, ExamplesAtSeveralSizes) {
  for (const auto& file : example_files())
    for (FrameSize frame : {FrameSize{1280, 720}, FrameSize{1920, 1080}, FrameSize{1, 1}, FrameSize{7680, 4320}}) {
      CompileOptions options;
      options.frame = frame;
      Plan plan = compile_or_throw(load_example(file), builtin_registry(), options);
      EXPECT_EQ(check_memory(plan, options.alias), "") << file;
    }
}

TEST(PlanAliasChecker, ThousandRandomGraphs) {
  size_t checked = 0, shared_bytes = 0;
  for (const DagCase& c : dag_cases(1000)) {
    Plan plan = compile_or_throw(make_random_dag(c.dag), synthetic_registry(), c.options);
    ASSERT_EQ(check_memory(plan, c.options.alias), "") << "nodes " << c.dag.nodes << " seed " << c.dag.seed;
    ++checked;
    shared_bytes += plan.memory.transient < plan.memory.transient_unaliased;
  }
  EXPECT_EQ(checked, 1000u);
  // Most random graphs do share memory; if none did, the checker above would test little.
  EXPECT_GT(shared_bytes, 700u);
}

TEST(PlanAliasChecker, DefaultExampleSavesAtLeastFortyPercentAt1080p) {
  CompileOptions options;
  options.frame = {1920, 1080};
  Plan plan = compile_or_throw(load_example("examples/default.json"), builtin_registry(), options);
  double saving = 1.0 - static_cast<double>(plan.memory.transient) / static_cast<double>(plan.memory.transient_unaliased);
  std::printf("default example at 1920x1080: %.1f MiB aliased, %.1f MiB one allocation each, saving %.1f%%\n",
              plan.memory.transient / 1048576.0, plan.memory.transient_unaliased / 1048576.0, 100 * saving);
  EXPECT_GE(saving, 0.40);
}

}  // namespace
}  // namespace lg::test
