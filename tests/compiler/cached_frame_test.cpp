// A frame whose cached passes are skipped (their keys unchanged) skips the barriers before
// them and those marked skip_when_cached. Replaying such a frame from where the last full frame
// left each cached image must give every dynamic access the layout it had in a full frame.
#include <gtest/gtest.h>

#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

// Layout of resource r at each of its dynamic accesses, replaying the frame from `start`;
// `skipping` leaves out static passes and their hand-over barriers. Returns the layouts and
// sets `problem` when a barrier's old layout does not match.
std::vector<Layout> replay(const Plan& plan, int r, Layout start, bool skipping, Layout* end, std::string* problem) {
  std::vector<Layout> seen;
  Layout layout = start;
  size_t next = 0;
  for (int pos = 0; pos < static_cast<int>(plan.passes.size()); ++pos) {
    bool skipped = skipping && plan.passes[pos].is_static;
    for (; next < plan.barriers.size() && plan.barriers[next].before <= pos; ++next) {
      const Barrier& b = plan.barriers[next];
      if (b.resource != r || (skipping && (skipped || b.skip_when_cached))) continue;
      if (b.old_layout != layout && b.old_layout != Layout::undefined && problem->empty())
        *problem = "barrier before " + plan.passes[pos].name + " expects another layout";
      layout = b.new_layout;
    }
    if (skipped) continue;
    for (const auto& a : plan.accesses_of(plan.passes[pos]))
      if (a.resource == r && !plan.passes[pos].is_static) seen.push_back(layout);
  }
  *end = layout;
  return seen;
}

void check_cached_frames(const Plan& plan, const std::string& what) {
  for (const Barrier& b : plan.barriers) {
    if (!b.skip_when_cached) continue;
    EXPECT_EQ(plan.resources[b.resource].desc.lifetime, ResourceLifetime::cached) << what;
    EXPECT_FALSE(plan.passes[b.before].is_static) << what;
  }
  for (size_t r = 0; r < plan.resources.size(); ++r) {
    if (plan.resources[r].desc.lifetime != ResourceLifetime::cached || plan.resources[r].first < 0) continue;
    std::string problem;
    Layout end = Layout::none;
    Layout start = plan.resources[r].desc.kind == ResourceKind::buffer ? Layout::none : Layout::undefined;
    std::vector<Layout> full = replay(plan, static_cast<int>(r), start, false, &end, &problem);
    Layout ignored;
    std::vector<Layout> cached = replay(plan, static_cast<int>(r), end, true, &ignored, &problem);
    EXPECT_EQ(problem, "") << what << ": " << plan.resources[r].desc.name;
    EXPECT_EQ(cached, full) << what << ": " << plan.resources[r].desc.name << " is read in another layout on cached frames";
  }
}

TEST(CompilerCachedFrames, ExamplesReadCachedResultsInTheirLayoutWhenStaticPassesAreSkipped) {
  size_t handoffs = 0;
  for (const auto& path : test::example_paths())
    for (const auto& scene : test::scene_paths()) {
      Plan plan = test::compile_example(path, scene);
      for (const Barrier& b : plan.barriers) handoffs += b.skip_when_cached;
      check_cached_frames(plan, path + " " + scene);
    }
  EXPECT_GT(handoffs, 0u);  // the examples do cache results, so the check above has work
}

TEST(CompilerCachedFrames, RandomDagsReadCachedResultsInTheirLayoutWhenStaticPassesAreSkipped) {
  for (const auto& c : test::dag_cases(300, 7)) {
    Plan plan = test::compile_ok(test::make_random_dag(c.dag), test::synthetic_registry(), c.options);
    check_cached_frames(plan, c.describe());
    if (testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace lg
