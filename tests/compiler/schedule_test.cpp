// Phase 7, schedule: the order is a permutation of the passes that respects every dependency
// (checked against pass_dependencies and, independently, against every pair of passes that
// share a resource with a write between them), with the static passes as one prefix.
#include "graph/compiler/schedule.h"

#include <gtest/gtest.h>

#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

void expect_valid_schedule(const LoweredGraph& lowered, const CachedVector<int>& order, const std::string& what) {
  const size_t count = lowered.passes.size();
  ASSERT_EQ(order.size(), count) << what;
  std::vector<int> position(count, -1);
  for (size_t k = 0; k < count; ++k) {
    ASSERT_GE(order[k], 0) << what;
    ASSERT_LT(order[k], static_cast<int>(count)) << what;
    ASSERT_EQ(position[order[k]], -1) << what << ": pass scheduled twice";
    position[order[k]] = static_cast<int>(k);
  }
  // Every dependency the phase itself reports.
  auto deps = pass_dependencies(lowered);
  for (size_t p = 0; p < count; ++p)
    for (int q : deps[p])
      EXPECT_LT(position[q], position[p])
          << what << ": " << lowered.passes[p].name << " needs " << lowered.passes[q].name;

  // Independently: lowering order is valid, so any two passes that touch one resource, one of
  // them writing, keep their lowering order. This also catches a dependency the phase forgot.
  std::vector<std::vector<std::pair<int, bool>>> users(lowered.resources.size());  // (pass, writes)
  for (size_t p = 0; p < count; ++p)
    for (const auto& a : lowered.passes[p].accesses)
      users[a.resource].push_back({static_cast<int>(p), usage_writes(a.usage)});
  for (size_t r = 0; r < users.size(); ++r)
    for (size_t i = 0; i < users[r].size(); ++i)
      for (size_t j = i + 1; j < users[r].size(); ++j) {
        auto [a, wa] = users[r][i];
        auto [b, wb] = users[r][j];
        if (a == b || !(wa || wb)) continue;
        EXPECT_LT(position[a], position[b]) << what << ": " << lowered.passes[a].name << " and "
                                            << lowered.passes[b].name << " on " << lowered.resources[r].name;
      }

  // Static passes first, as one block, and they only ever wait for static passes.
  bool seen_dynamic = false;
  for (int p : order) {
    if (!lowered.passes[p].is_static)
      seen_dynamic = true;
    else
      EXPECT_FALSE(seen_dynamic) << what << ": static " << lowered.passes[p].name << " after a per-frame pass";
  }
  for (size_t p = 0; p < count; ++p) {
    if (!lowered.passes[p].is_static) continue;
    for (int q : deps[p]) EXPECT_TRUE(lowered.passes[q].is_static) << what << ": " << lowered.passes[p].name;
  }
}

std::vector<std::string> names(const LoweredGraph& lowered, const CachedVector<int>& order) {
  std::vector<std::string> out;
  for (int p : order) out.push_back(lowered.passes[p].name);
  return out;
}

TEST(CompilerSchedule, PassDependenciesOfOneResource) {
  // P0 writes R, P1 reads it, P2 writes it again, P3 reads it: RAW, WAR + WAW, RAW.
  LoweredGraph g;
  g.resources.resize(1);
  g.resources[0].name = "r";
  auto pass = [&](std::string name, Usage u) {
    LoweredPass p;
    p.name = std::move(name);
    p.accesses.push_back({0, u});
    g.passes.push_back(p);
  };
  pass("w0", Usage::storage_write);
  pass("r1", Usage::sampled);
  pass("w2", Usage::storage_read_write);
  pass("r3", Usage::sampled);
  auto deps = pass_dependencies(g);
  auto sorted = [](std::span<const int> list) {  // as a set: listing a dependency twice is harmless
    std::vector<int> v(list.begin(), list.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  };
  EXPECT_EQ(sorted(deps[0]), std::vector<int>{});
  EXPECT_EQ(sorted(deps[1]), std::vector<int>{0});
  EXPECT_EQ(sorted(deps[2]), (std::vector<int>{0, 1}));
  EXPECT_EQ(sorted(deps[3]), std::vector<int>{2});
  EXPECT_EQ(schedule(g), (CachedVector<int>{0, 1, 2, 3}));
}

TEST(CompilerSchedule, ExamplesRespectEveryDependency) {
  for (const auto& path : test::example_paths())
    for (const auto& scene : test::scene_paths()) {
      CompileOptions o;
      o.scene = test::load_scene(scene);
      auto l = test::lower_graph(test::load_example(path), builtin_registry(), o);
      expect_valid_schedule(l->lowered, schedule(l->lowered), path + " " + scene);
    }
}

TEST(CompilerSchedule, RandomDagsRespectEveryDependency) {
  int checked = 0;
  for (const auto& c : test::dag_cases(300, 2)) {
    auto l = test::lower_graph(test::make_random_dag(c.dag), test::synthetic_registry(), c.options);
    expect_valid_schedule(l->lowered, schedule(l->lowered), c.describe());
    if (HasFailure()) break;
    ++checked;
  }
  EXPECT_EQ(checked, 300);
}

TEST(CompilerSchedule, EachProducerRunsJustBeforeItsFirstConsumer) {
  auto chain = test::lower_graph(test::make_chain(4), test::synthetic_registry());
  EXPECT_EQ(names(chain->lowered, schedule(chain->lowered)),
            (std::vector<std::string>{"n0/make", "n1/down", "n1/up", "n2/down", "n2/up"}));

  // The shadow map is drawn right before the pass that samples it, not at the start.
  auto minimal = test::lower_graph(test::load_example("examples/minimal.json"), builtin_registry());
  EXPECT_EQ(names(minimal->lowered, schedule(minimal->lowered)),
            (std::vector<std::string>{"gbuf/raster", "light/shadows", "light/direct", "light/area", "tonemap/map"}));
}

TEST(CompilerSchedule, StaticPassesAreHoistedEvenWhenListedLast) {
  // Env nodes whose ids sort after every per-frame node still run first.
  Graph g = test::load_example("examples/default.json");
  for (auto& n : g.nodes)
    if (n.id == "sky" || n.id == "sh" || n.id == "specular" || n.id == "dfg") n.id = "zz_" + n.id;
  for (auto& l : g.links) {
    for (PortRef* ref : {&l.from, &l.to})
      if (ref->node == "sky" || ref->node == "sh" || ref->node == "specular" || ref->node == "dfg")
        ref->node = "zz_" + ref->node;
  }
  auto l = test::lower_graph(std::move(g), builtin_registry());
  auto order = schedule(l->lowered);
  expect_valid_schedule(l->lowered, order, "renamed");
  auto n = names(l->lowered, order);
  ASSERT_GE(n.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(n[k].starts_with("zz_")) << n[k];
}

}  // namespace
}  // namespace lg
