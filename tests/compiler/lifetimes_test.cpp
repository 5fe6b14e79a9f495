// Phase 8, lifetimes: a resource lives from the first to the last scheduled pass that touches
// it; results of the frame to its end; cached and history resources across the whole frame.
#include "graph/compiler/lifetimes.h"

#include <gtest/gtest.h>

#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

// Recomputes each plan resource's range from the passes that use it.
void expect_lifetimes_cover_uses(const Plan& plan, const std::string& what) {
  const int end = static_cast<int>(plan.passes.size()) - 1;
  std::vector<int> first(plan.resources.size(), -1), last(plan.resources.size(), -1);
  for (int p = 0; p <= end; ++p)
    for (const auto& a : plan.accesses_of(plan.passes[p])) {
      if (first[a.resource] < 0) first[a.resource] = p;
      last[a.resource] = p;
    }
  for (size_t r = 0; r < plan.resources.size(); ++r) {
    const PlanResource& res = plan.resources[r];
    SCOPED_TRACE(what + ": " + res.desc.name);
    if (first[r] < 0) {
      EXPECT_EQ(res.first, -1);
      EXPECT_EQ(res.last, -1);
      EXPECT_EQ(res.placement.block, -1) << "an unused resource takes no memory";
      continue;
    }
    switch (res.desc.lifetime) {
      case ResourceLifetime::transient:
        EXPECT_EQ(res.first, first[r]);
        EXPECT_EQ(res.last, last[r]);
        break;
      case ResourceLifetime::exported:
        EXPECT_EQ(res.first, first[r]);
        EXPECT_EQ(res.last, end) << "a result of the frame lives to its end";
        break;
      case ResourceLifetime::cached:
      case ResourceLifetime::history:
        EXPECT_EQ(res.first, 0) << "kept across frames";
        EXPECT_EQ(res.last, end) << "kept across frames";
        break;
    }
  }
}

TEST(CompilerLifetimes, CoverFirstToLastUseOnTheExamples) {
  for (const auto& path : test::example_paths())
    for (const auto& scene : test::scene_paths())
      expect_lifetimes_cover_uses(test::compile_example(path, scene), path + " " + scene);
}

TEST(CompilerLifetimes, CoverFirstToLastUseOnRandomDags) {
  for (const auto& c : test::dag_cases(200, 3)) {
    expect_lifetimes_cover_uses(test::compile_ok(test::make_random_dag(c.dag), test::synthetic_registry(), c.options),
                                c.describe());
    if (HasFailure()) break;
  }
}

TEST(CompilerLifetimes, ExamplesReadLikeAFrame) {
  Plan plan = test::compile_example("examples/default.json");
  auto range = [&](std::string_view name) {
    int r = test::resource_at(plan, name);
    return r < 0 ? std::pair{-2, -2} : std::pair{plan.resources[r].first, plan.resources[r].last};
  };
  auto at = [&](std::string_view pass) { return test::pass_at(plan, pass); };
  const int end = static_cast<int>(plan.passes.size()) - 1;
  // The shadow map lives from its draw to the direct-light pass, not longer.
  EXPECT_EQ(range("light/shadow_map"), (std::pair{at("light/shadows"), at("light/direct")}));
  // Depth is read last by the IBL pass; motion vectors last by the AO denoiser.
  EXPECT_EQ(range("gbuf.gbuffer.depth"), (std::pair{at("gbuf/raster"), at("ibl/shade")}));
  EXPECT_EQ(range("gbuf.gbuffer.motion"), (std::pair{at("gbuf/raster"), at("gtao/denoise")}));
  EXPECT_EQ(range("tonemap.color"), (std::pair{at("tonemap/map"), end}));  // exported
  EXPECT_EQ(range("sky.cube"), (std::pair{0, end}));                       // cached
  EXPECT_EQ(range("gtao.ao"), (std::pair{0, end}));                        // history
}

TEST(CompilerLifetimes, PhaseAloneOnAHandMadeGraph) {
  LoweredGraph g;
  g.resources.resize(4);
  g.resources[1].lifetime = ResourceLifetime::exported;
  g.resources[2].lifetime = ResourceLifetime::cached;
  // resource 3: nothing touches it
  for (int p = 0; p < 4; ++p) g.passes.emplace_back();
  g.passes[1].accesses = {{0, Usage::storage_write}};
  g.passes[2].accesses = {{0, Usage::sampled}, {1, Usage::storage_write}};
  g.passes[3].accesses = {{2, Usage::storage_write}};
  // Scheduled as 3, 1, 2, 0.
  auto lives = lifetimes(g, {3, 1, 2, 0});
  EXPECT_EQ(lives[0].first, 1);
  EXPECT_EQ(lives[0].last, 2);
  EXPECT_EQ(lives[1].first, 2);
  EXPECT_EQ(lives[1].last, 3);  // exported: to the end
  EXPECT_EQ(lives[2].first, 0);
  EXPECT_EQ(lives[2].last, 3);  // cached: the whole frame
  EXPECT_FALSE(lives[3].used());
}

}  // namespace
}  // namespace lg
