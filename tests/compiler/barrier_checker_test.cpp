// Barriers checked from the access rules alone, without synchronize.cpp: from each plan's
// passes (accesses in schedule order) derive every hazard, then require exactly one barrier to
// cover each, no barrier that covers none, image layouts that chain from barrier to barrier and
// match every access, and a chain of barriers ordering every conflicting pair of accesses.
#include <gtest/gtest.h>

#include <map>

#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

// ---- the access rules, written down from the spec, not from synchronize.cpp ----

struct Use {
  int pos = -1;  // schedule position
  uint32_t stages = 0, access = 0;
  bool writes = false;
  Layout layout = Layout::none;
};

Use rule(Usage u, Queue q, const LoweredResource& r) {
  const bool buffer = r.kind == ResourceKind::buffer;
  const uint32_t shader = q == Queue::compute ? stage_compute_shader : stage_fragment_shader;
  const uint32_t depth_stages = stage_early_fragment_tests | stage_late_fragment_tests;
  const uint32_t depth_access = access_depth_stencil_attachment_read | access_depth_stencil_attachment_write;
  const Layout storage = buffer ? Layout::none : Layout::general;
  switch (u) {
    case Usage::sampled:
      return {-1, shader, access_shader_sampled_read, false, buffer ? Layout::none : Layout::read_only};
    case Usage::storage_read:
      return {-1, shader, access_shader_storage_read, false, storage};
    case Usage::storage_write:
      return {-1, shader, access_shader_storage_write, true, storage};
    case Usage::storage_read_write:
      return {-1, shader, access_shader_storage_read | access_shader_storage_write, true, storage};
    case Usage::attachment_write:
      return r.depth_format
                 ? Use{-1, depth_stages, depth_access, true, Layout::attachment}
                 : Use{-1, stage_color_attachment_output, access_color_attachment_write, true, Layout::attachment};
    case Usage::attachment_blend:
      return r.depth_format
                 ? Use{-1, depth_stages, depth_access, true, Layout::attachment}
                 : Use{-1, stage_color_attachment_output, access_color_attachment_read | access_color_attachment_write,
                       true, Layout::attachment};
    case Usage::buffer_read:
      return {-1, shader, access_shader_storage_read | access_uniform_read, false, Layout::none};
    case Usage::buffer_write:
      return {-1, shader, access_shader_storage_write, true, Layout::none};
  }
  return {};
}

bool covers(uint32_t have, uint32_t need) {
  return (have & need) == need;
}

struct Hazard {
  int resource = -1;
  int e_pos = -1;  // the earlier access; -1 when it is outside this frame (or there is none)
  uint32_t e_stages = 0, e_writes = 0;
  Use later;
  std::vector<BarrierReason> reasons;  // what the covering barrier may say
  std::string what;
};

// Every problem in the barriers of `plan`, one per line; empty when they are right.
std::string check_barriers(const Plan& plan) {
  std::string problems;
  auto fail = [&](const std::string& s) {
    if (problems.size() < 4000) problems += s + "\n";
  };
  const size_t count = plan.resources.size();
  auto name = [&](int r) { return plan.resources[r].desc.name; };
  auto pass_name = [&](int pos) { return pos < 0 ? std::string("(last frame)") : plan.passes[pos].name; };

  // Each pass's use of each resource, combined: a pass that reads a resource two ways needs both
  // at once, in one layout (GENERAL when the ways disagree).
  std::vector<std::vector<Use>> uses(count);
  for (int pos = 0; pos < static_cast<int>(plan.passes.size()); ++pos) {
    const PlanPass& pass = plan.passes[pos];
    for (const auto& a : plan.accesses_of(pass)) {
      Use u = rule(a.usage, pass.queue, plan.resources[a.resource].desc);
      u.pos = pos;
      auto& list = uses[a.resource];
      if (!list.empty() && list.back().pos == pos) {
        Use& v = list.back();
        v.stages |= u.stages;
        v.access |= u.access;
        v.writes |= u.writes;
        if (v.layout != u.layout) v.layout = Layout::general;
      } else {
        list.push_back(u);
      }
    }
  }
  // Runs: a write alone, or consecutive reads in one layout (they need nothing between them).
  std::vector<std::vector<std::vector<Use>>> runs(count);
  for (size_t r = 0; r < count; ++r)
    for (size_t k = 0; k < uses[r].size(); ++k) {
      const Use& u = uses[r][k];
      bool joins = k > 0 && !u.writes && !uses[r][k - 1].writes && u.layout == uses[r][k - 1].layout;
      if (joins)
        runs[r].back().push_back(u);
      else
        runs[r].push_back({u});
    }
  std::vector<int> copy_of(count, -1);  // a history resource's previous-frame copy
  for (size_t r = 0; r < count; ++r)
    if (plan.resources[r].desc.history_of >= 0) copy_of[plan.resources[r].desc.history_of] = static_cast<int>(r);

  // ---- the hazards ----
  std::vector<Hazard> hazards;
  auto add = [&](int r, int e_pos, uint32_t e_stages, uint32_t e_access, const Use& l,
                 std::vector<BarrierReason> reasons, std::string what) {
    hazards.push_back({r, e_pos, e_stages, e_access & access_write_mask, l, std::move(reasons), std::move(what)});
  };
  for (size_t ri = 0; ri < count; ++ri) {
    const int r = static_cast<int>(ri);
    const auto& rr = runs[r];
    if (rr.empty()) continue;
    const LoweredResource& desc = plan.resources[r].desc;
    const bool image = desc.kind != ResourceKind::buffer;
    // Between consecutive runs: every access of one against every access of the next.
    for (size_t k = 1; k < rr.size(); ++k)
      for (const Use& e : rr[k - 1])
        for (const Use& l : rr[k]) {
          BarrierReason why = e.writes && l.writes ? BarrierReason::write_after_write
                              : e.writes           ? BarrierReason::read_after_write
                              : l.writes           ? BarrierReason::write_after_read
                                                   : BarrierReason::layout_transition;
          add(r, e.pos, e.stages, e.access, l, {why}, std::string(barrier_reason_name(why)));
        }
    // Before the first run.
    const std::vector<Use>& first = rr.front();
    if (desc.history_of >= 0) {
      // Its bytes were the partner's last frame: wait for the partner's last run, unless both
      // are reads in one layout.
      const auto& partner = runs[desc.history_of];
      if (!partner.empty()) {
        const auto& last = partner.back();
        bool quiet = !last.front().writes && !first.front().writes && last.front().layout == first.front().layout;
        if (!quiet)
          for (const Use& e : last)
            for (const Use& l : first) add(r, -1, e.stages, e.access, l, {BarrierReason::history}, "history (copy)");
      } else if (image) {
        for (const Use& l : first) add(r, -1, 0, 0, l, {BarrierReason::history, BarrierReason::first_use}, "first use");
      }
      continue;
    }
    std::vector<BarrierReason> start_reasons = {BarrierReason::first_use};
    if (copy_of[r] >= 0) {
      start_reasons = {BarrierReason::history};
      if (!runs[copy_of[r]].empty())
        for (const Use& e : runs[copy_of[r]].back())
          for (const Use& l : first) add(r, -1, e.stages, e.access, l, start_reasons, "history (current)");
    } else if (plan.resources[r].placement.predecessor_count > 0) {
      start_reasons = {BarrierReason::alias};
      for (int p : plan.predecessors_of(r)) {
        if (runs[p].empty()) {
          fail(name(r) + ": predecessor " + name(p) + " is never used");
          continue;
        }
        for (const Use& e : runs[p].back())
          for (const Use& l : first) add(r, e.pos, e.stages, e.access, l, start_reasons, "alias after " + name(p));
      }
    }
    if (image)
      for (const Use& l : first) add(r, -1, 0, 0, l, start_reasons, "first use");
  }

  // ---- exactly one barrier covers each hazard; each barrier covers one at least ----
  std::vector<std::vector<int>> barriers_of(count);
  for (size_t b = 0; b < plan.barriers.size(); ++b) {
    const Barrier& x = plan.barriers[b];
    if (x.resource < 0 || x.resource >= static_cast<int>(count) || x.before < 0 ||
        x.before >= static_cast<int>(plan.passes.size())) {
      fail("barrier " + std::to_string(b) + " points outside the plan");
      return problems;
    }
    if (b > 0 && plan.barriers[b - 1].before > x.before) fail("barriers are not sorted by the pass they precede");
    if (x.src_access & ~access_write_mask) fail(name(x.resource) + ": a barrier makes a read available");
    if (x.dst_stages == 0) fail(name(x.resource) + ": a barrier waits in no stage");
    barriers_of[x.resource].push_back(static_cast<int>(b));
  }
  std::vector<int> covered(plan.barriers.size(), 0);
  for (const Hazard& h : hazards) {
    std::vector<int> by;
    for (int b : barriers_of[h.resource]) {
      const Barrier& x = plan.barriers[b];
      if (x.before > h.e_pos && x.before <= h.later.pos && covers(x.src_stages, h.e_stages) &&
          covers(x.src_access, h.e_writes) && covers(x.dst_stages, h.later.stages) &&
          covers(x.dst_access, h.later.access))
        by.push_back(b);
    }
    std::string where =
        name(h.resource) + ": " + h.what + " from " + pass_name(h.e_pos) + " to " + pass_name(h.later.pos);
    if (by.size() != 1) {
      fail(where + " is covered by " + std::to_string(by.size()) + " barriers");
      continue;
    }
    ++covered[by[0]];
    BarrierReason got = plan.barriers[by[0]].reason;
    if (std::find(h.reasons.begin(), h.reasons.end(), got) == h.reasons.end())
      fail(where + ": the barrier says '" + std::string(barrier_reason_name(got)) + "'");
  }
  for (size_t b = 0; b < plan.barriers.size(); ++b)
    if (!covered[b])
      fail(name(plan.barriers[b].resource) + ": barrier before " + pass_name(plan.barriers[b].before) + " (" +
           std::string(barrier_reason_name(plan.barriers[b].reason)) + ") covers no hazard");

  // ---- layouts chain from barrier to barrier and match every access ----
  for (size_t ri = 0; ri < count; ++ri) {
    const int r = static_cast<int>(ri);
    const LoweredResource& desc = plan.resources[r].desc;
    const bool image = desc.kind != ResourceKind::buffer;
    Layout current = image ? Layout::undefined : Layout::none;
    if (desc.history_of >= 0 && !runs[desc.history_of].empty()) current = runs[desc.history_of].back().front().layout;
    size_t next_use = 0, next_barrier = 0;
    const auto& bl = barriers_of[r];
    for (int pos = 0; pos < static_cast<int>(plan.passes.size()); ++pos) {
      for (; next_barrier < bl.size() && plan.barriers[bl[next_barrier]].before == pos; ++next_barrier) {
        const Barrier& x = plan.barriers[bl[next_barrier]];
        bool writes_here = next_use < uses[r].size() && uses[r][next_use].pos == pos && uses[r][next_use].writes;
        if (!image) {
          if (x.old_layout != Layout::none || x.new_layout != Layout::none)
            fail(name(r) + ": a buffer barrier with layouts");
          continue;
        }
        // UNDEFINED as the old layout discards the contents: fine only right before a write.
        if (x.old_layout != current && !(x.old_layout == Layout::undefined && writes_here))
          fail(name(r) + " before " + pass_name(pos) + ": barrier from " + std::string(layout_name(x.old_layout)) +
               " but the image is " + std::string(layout_name(current)));
        if (x.new_layout == Layout::undefined) fail(name(r) + ": a barrier into UNDEFINED");
        current = x.new_layout;
      }
      if (next_use < uses[r].size() && uses[r][next_use].pos == pos) {
        if (uses[r][next_use].layout != current)
          fail(name(r) + " in " + pass_name(pos) + ": used as " + std::string(layout_name(uses[r][next_use].layout)) +
               " while " + std::string(layout_name(current)));
        ++next_use;
      }
    }
  }

  // ---- every conflicting pair of accesses is ordered by a chain of barriers ----
  // Execution chains across any barriers: the first one's source stages include the earlier
  // access's, each next one's source stages meet the previous one's destination stages.
  auto reached = [&](int e_pos, uint32_t e_stages, int until) {
    std::vector<uint32_t> at(plan.passes.size(), 0);  // stages ordered after e by the barriers before pos
    uint32_t now = 0;
    size_t b = 0;
    while (b < plan.barriers.size() && plan.barriers[b].before <= e_pos) ++b;
    for (int pos = e_pos + 1; pos <= until; ++pos) {
      for (; b < plan.barriers.size() && plan.barriers[b].before == pos; ++b) {
        const Barrier& x = plan.barriers[b];
        if (covers(x.src_stages, e_stages) || (x.src_stages & now)) now |= x.dst_stages;
      }
      at[pos] = now;
    }
    return at;
  };
  for (size_t ri = 0; ri < count; ++ri) {
    const auto& u = uses[ri];
    for (size_t i = 0; i + 1 < u.size(); ++i) {
      auto at = reached(u[i].pos, u[i].stages, u.back().pos);
      for (size_t j = i + 1; j < u.size(); ++j)
        if ((u[i].writes || u[j].writes || u[i].layout != u[j].layout) && !covers(at[u[j].pos], u[j].stages))
          fail(name(static_cast<int>(ri)) + ": " + pass_name(u[i].pos) + " and " + pass_name(u[j].pos) +
               " are not ordered");
    }
  }
  // Memory handed over: everything that held bytes before (not only the last holder) is done
  // with them before the new resource's first run.
  std::vector<int> placed;
  for (size_t r = 0; r < count; ++r)
    if (plan.resources[r].placement.block == 0 && plan.resources[r].first >= 0) placed.push_back(static_cast<int>(r));
  for (int q : placed) {
    const PlanResource& pq = plan.resources[q];
    std::vector<int> later;
    int until = -1;
    for (int r : placed) {
      const PlanResource& pr = plan.resources[r];
      if (pr.first > pq.last && pr.placement.offset < pq.placement.offset + pq.placement.size &&
          pq.placement.offset < pr.placement.offset + pr.placement.size) {
        later.push_back(r);
        until = std::max(until, runs[r].front().back().pos);
      }
    }
    if (later.empty()) continue;
    for (const Use& e : runs[q].back()) {
      auto at = reached(e.pos, e.stages, until);
      for (int r : later)
        for (const Use& l : runs[r].front())
          if (!covers(at[l.pos], l.stages))
            fail(name(r) + " in " + pass_name(l.pos) + " reuses bytes of " + name(q) + " before " + pass_name(e.pos) +
                 " is done");
    }
  }
  return problems;
}

// ---- runs ----

TEST(CompilerBarrierChecker, Examples) {
  int checked = 0;
  for (const auto& path : test::example_paths())
    for (const auto& scene : test::scene_paths())
      for (bool alias : {true, false}) {
        CompileOptions o;
        o.scene = test::load_scene(scene);
        o.alias.enabled = alias;
        Plan plan = test::compile_ok(test::load_example(path), builtin_registry(), o);
        EXPECT_EQ(check_barriers(plan), "") << path << " " << scene << (alias ? "" : " (no aliasing)");
        ++checked;
      }
  EXPECT_EQ(checked, static_cast<int>(test::example_paths().size() * test::scene_paths().size() * 2));
  EXPECT_GE(checked, 24);
}

TEST(CompilerBarrierChecker, ExamplesWithoutShadowsOrEnvironment) {
  SceneSummary s = default_scene_summary();
  s.shadows = false;
  s.environment = false;
  s.aperture = 0.1;
  for (const auto& path : test::example_paths()) {
    CompileOptions o;
    o.scene = s;
    EXPECT_EQ(check_barriers(test::compile_ok(test::load_example(path), builtin_registry(), o)), "") << path;
  }
}

TEST(CompilerBarrierChecker, ThousandRandomDags) {
  int checked = 0;
  size_t barriers = 0;
  std::map<BarrierReason, int> reasons;
  for (const auto& c : test::dag_cases(1000, 5)) {
    Graph g = test::make_random_dag(c.dag);
    if (c.dag.seed % 2) g = test::with_history_from_elsewhere(std::move(g), c.dag.seed);
    Plan plan = test::compile_ok(g, test::synthetic_registry(), c.options);
    std::string problems = check_barriers(plan);
    EXPECT_EQ(problems, "") << c.describe();
    if (!problems.empty()) break;
    barriers += plan.barriers.size();
    for (const auto& b : plan.barriers) ++reasons[b.reason];
    ++checked;
  }
  EXPECT_EQ(checked, 1000);
  // Every kind of barrier the synthetic nodes can need occurs in the sweep, so the rules above
  // were exercised. (No synthetic node overwrites what it read: write-after-read is covered by
  // the hand-made schemas below.)
  for (BarrierReason r :
       {BarrierReason::first_use, BarrierReason::alias, BarrierReason::history, BarrierReason::read_after_write,
        BarrierReason::write_after_write, BarrierReason::layout_transition})
    EXPECT_GT(reasons[r], 0) << barrier_reason_name(r);
  EXPECT_GT(barriers, 10000u);
}

// Node types no built-in or synthetic schema has yet: a pass that overwrites what an earlier pass
// of the node read (write after read), and a pass that reads one image through two inputs in
// two different ways at once, after an earlier pass sampled it.
const char* const odd_schemas[] = {
    R"({ "type": "odd.source", "doc": "An image.",
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "frame", "doc": "Image." } ],
         "passes": [ { "name": "make", "queue": "compute", "uses": { "out.out": "storage_write" } } ] })",
    R"({ "type": "odd.refill", "doc": "Fills a temporary, reads it, fills it again, reads it again.",
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "In." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:a", "doc": "Out." } ],
         "resources": [ { "name": "tmp", "type": "texture2d:hdr", "extent": "input:a", "doc": "Temporary." } ],
         "passes": [
           { "name": "fill", "queue": "compute", "uses": { "in.a": "sampled", "tmp.tmp": "storage_write" } },
           { "name": "draw", "queue": "graphics", "uses": { "tmp.tmp": "sampled", "out.out": "attachment_write" } },
           { "name": "refill", "queue": "compute", "uses": { "tmp.tmp": "storage_write" } },
           { "name": "finish", "queue": "compute", "uses": { "tmp.tmp": "storage_read", "out.out": "storage_read_write" } } ] })",
    R"({ "type": "odd.two_ways", "doc": "Samples an image, then samples and loads it in one pass.",
         "inputs": [ { "name": "a", "type": "texture2d:hdr", "doc": "Sampled." },
                     { "name": "b", "type": "texture2d:hdr", "doc": "Loaded as storage." } ],
         "outputs": [ { "name": "out", "type": "texture2d:hdr", "extent": "input:a", "doc": "Out." } ],
         "passes": [
           { "name": "pre", "queue": "compute", "uses": { "in.a": "sampled", "out.out": "storage_write" } },
           { "name": "mix", "queue": "compute", "uses": { "in.a": "sampled", "in.b": "storage_read", "out.out": "storage_read_write" } } ] })",
    R"({ "type": "odd.sink", "doc": "A result.", "output": true,
         "inputs": [ { "name": "color", "type": "texture2d:*", "doc": "Result." } ] })",
};

const Registry& odd_registry() {
  static const Registry registry = [] {
    Registry r;
    for (const char* text : odd_schemas) {
      Diagnostics d("odd schema");
      if (!r.add_schema(text, d)) throw std::runtime_error(d.to_string());
    }
    return r;
  }();
  return registry;
}

TEST(CompilerBarrierChecker, WriteAfterReadInsideANode) {
  Graph g;
  test::add_node(g, "src", "odd.source");
  test::add_node(g, "x", "odd.refill");
  test::add_node(g, "out", "odd.sink");
  test::add_link(g, "src.out", "x.a");
  test::add_link(g, "x.out", "out.color");
  Plan plan = test::compile_ok(g, odd_registry());
  EXPECT_EQ(check_barriers(plan), "");
  int tmp = test::resource_at(plan, "x/tmp");
  int war = 0;
  for (const auto& b : plan.barriers)
    if (b.resource == tmp && b.reason == BarrierReason::write_after_read) {
      ++war;
      EXPECT_EQ(b.before, test::pass_at(plan, "x/refill"));
      EXPECT_EQ(b.src_stages, uint32_t{stage_fragment_shader});  // the graphics pass sampled it
      EXPECT_EQ(b.src_access, uint32_t{access_none});
    }
  EXPECT_EQ(war, 1);
}

TEST(CompilerBarrierChecker, OnePassReadingAnImageTwoWays) {
  // src.out is sampled by x/pre, then sampled and loaded by x/mix: x/mix needs it in GENERAL,
  // and the barrier before it must make it visible to both kinds of read.
  Graph g;
  test::add_node(g, "src", "odd.source");
  test::add_node(g, "x", "odd.two_ways");
  test::add_node(g, "out", "odd.sink");
  test::add_link(g, "src.out", "x.a");
  test::add_link(g, "src.out", "x.b");
  test::add_link(g, "x.out", "out.color");
  Plan plan = test::compile_ok(g, odd_registry());
  EXPECT_EQ(check_barriers(plan), "");
}

TEST(CompilerBarrierChecker, TheCheckerCatchesBrokenBarriers) {
  Plan good = test::compile_example("examples/default.json");
  ASSERT_EQ(check_barriers(good), "");
  auto find = [&](std::string_view resource, BarrierReason reason) {
    for (size_t b = 0; b < good.barriers.size(); ++b)
      if (good.resources[good.barriers[b].resource].desc.name == resource && good.barriers[b].reason == reason)
        return b;
    throw std::runtime_error("no such barrier");
  };
  size_t raw = find("light.color", BarrierReason::read_after_write);

  Plan missing = good;
  missing.barriers.erase(missing.barriers.begin() + static_cast<long>(raw));
  EXPECT_NE(check_barriers(missing).find("covered by 0 barriers"), std::string::npos);

  Plan twice = good;
  twice.barriers.insert(twice.barriers.begin() + static_cast<long>(raw), good.barriers[raw]);
  EXPECT_NE(check_barriers(twice).find("covered by 2 barriers"), std::string::npos);

  Plan narrow = good;  // waits for the wrong stage
  narrow.barriers[raw].src_stages = stage_fragment_shader;
  EXPECT_NE(check_barriers(narrow).find("covered by 0 barriers"), std::string::npos);

  Plan invisible = good;  // the write is never made available
  invisible.barriers[raw].src_access = access_none;
  EXPECT_NE(check_barriers(invisible).find("covered by 0 barriers"), std::string::npos);

  Plan layout = good;
  layout.barriers[raw].new_layout = Layout::general;
  EXPECT_NE(check_barriers(layout).find("used as READ_ONLY_OPTIMAL while GENERAL"), std::string::npos)
      << check_barriers(layout);

  Plan extra = good;  // a barrier between two reads in one layout
  Barrier b = good.barriers[find("gbuf.gbuffer.depth", BarrierReason::read_after_write)];
  b.before = test::pass_at(good, "ibl/shade");
  b.reason = BarrierReason::layout_transition;
  b.src_stages = b.dst_stages;
  b.src_access = access_none;
  b.old_layout = b.new_layout;
  extra.barriers.push_back(b);
  std::stable_sort(extra.barriers.begin(), extra.barriers.end(),
                   [](const Barrier& x, const Barrier& y) { return x.before < y.before; });
  EXPECT_NE(check_barriers(extra).find("covers no hazard"), std::string::npos);

  Plan unordered = good;  // an alias hand-over that forgets what the old owner did
  size_t handover = find("light/shadow_map", BarrierReason::alias);
  unordered.barriers[handover].src_stages = stage_none;
  EXPECT_NE(check_barriers(unordered).find("reuses bytes of"), std::string::npos);
}

}  // namespace
}  // namespace lg
