// An independent check of the synchronize phase. From the plan's passes alone it derives, per
// resource, the layout each access needs and the hazards between accesses (read after write,
// write after read, write after write, a layout change between reads), then checks that
//   - every hazard is ordered by an execution-dependency chain of the resource's own barriers
//     between the two accesses (a barrier whose source stages meet what is ordered so far
//     extends the chain); ordering that happens to come from other resources' barriers does
//     not count, since it would break silently when the plan around it changes,
//   - the first barrier after a write makes that write available (its access is in src_access),
//   - each resource's barriers chain its layouts: old layout = the layout it is in,
//   - an image's first access follows a layout transition that waits for whatever held its
//     bytes (alias predecessors) or, for history pairs, the other half's last access,
//   - no barrier is redundant: dropping any one breaks one of the rules above,
//   - at most one barrier per resource sits before a pass.
#include <gtest/gtest.h>

#include <map>

#include "graph/compiler/barrier.h"
#include "tests/plan_checks/plan_fixtures.h"

namespace lg::test {
namespace {

struct Use {
  int pos;
  uint32_t stages, access;
  Layout layout;
  bool writes;
};

// The rules, restated from Vulkan and the usage names, not from synchronize.cpp.
Use use_of(int pos, const PlanPass& pass, const PlanAccess& a, const PlanResource& r) {
  bool buffer = r.desc.kind == ResourceKind::buffer;
  uint32_t shader = pass.queue == Queue::compute ? stage_compute_shader : stage_fragment_shader;
  switch (a.usage) {
    case Usage::sampled: return {pos, shader, access_shader_sampled_read, buffer ? Layout::none : Layout::read_only, false};
    case Usage::storage_read: return {pos, shader, access_shader_storage_read, buffer ? Layout::none : Layout::general, false};
    case Usage::storage_write: return {pos, shader, access_shader_storage_write, buffer ? Layout::none : Layout::general, true};
    case Usage::storage_read_write:
      return {pos, shader, access_shader_storage_read | access_shader_storage_write, buffer ? Layout::none : Layout::general, true};
    case Usage::buffer_read: return {pos, shader, access_shader_storage_read, Layout::none, false};
    case Usage::buffer_write: return {pos, shader, access_shader_storage_write, Layout::none, true};
    case Usage::attachment_write:
    case Usage::attachment_blend:
      if (r.desc.depth_format)
        return {pos, stage_early_fragment_tests | stage_late_fragment_tests,
                access_depth_stencil_attachment_read | access_depth_stencil_attachment_write, Layout::attachment, true};
      return {pos, stage_color_attachment_output,
              access_color_attachment_write | (a.usage == Usage::attachment_blend ? access_color_attachment_read : 0u),
              Layout::attachment, true};
  }
  return {};
}

class Checker {
 public:
  explicit Checker(const Plan& plan) : plan_(plan), uses_(plan.resources.size()) {
    for (int pos = 0; pos < static_cast<int>(plan.passes.size()); ++pos)
      for (const PlanAccess& a : plan.passes[pos].accesses) {
        Use u = use_of(pos, plan.passes[pos], a, plan.resources[a.resource]);
        auto& list = uses_[a.resource];
        if (!list.empty() && list.back().pos == pos) {  // one pass, two uses: one combined access
          list.back().stages |= u.stages, list.back().access |= u.access, list.back().writes |= u.writes;
          if (list.back().layout != u.layout) list.back().layout = Layout::general;
        } else {
          list.push_back(u);
        }
      }
  }

  // Empty when `barriers` synchronize the plan, else the first problem found.
  std::string check(const std::vector<Barrier>& barriers) const {
    std::map<std::pair<int, int>, int> per_pass;  // (resource, pass) -> barriers
    for (const Barrier& b : barriers)
      if (++per_pass[{b.resource, b.before}] > 1) return "two barriers for " + name(b.resource) + " before one pass";
    std::vector<std::vector<const Barrier*>> own(uses_.size());
    for (const Barrier& b : barriers) own[b.resource].push_back(&b);
    for (size_t r = 0; r < uses_.size(); ++r) {
      std::string problem = check_resource(static_cast<int>(r), own[r]);
      if (!problem.empty()) return problem;
    }
    return {};
  }

  // The rules for one resource, given its own barriers in plan order.
  std::string check_resource(int r, const std::vector<const Barrier*>& own) const {
    const auto& list = uses_[r];
    if (list.empty()) return own.empty() ? "" : name(r) + " has barriers but no use";
    const PlanResource& res = plan_.resources[r];
    bool image = res.desc.kind != ResourceKind::buffer;
    return layout_and_hazards(r, res, image, list, own);
  }

 private:
  const Plan& plan_;
  std::vector<std::vector<Use>> uses_;

  std::string name(int r) const { return plan_.resources[r].desc.name; }

  // Whether barriers between positions (after, upto] order stages `from` before `to`.
  static bool chained(const std::vector<const Barrier*>& barriers, int after, int upto, uint32_t from, uint32_t to) {
    uint32_t ordered = from;  // stages already waited for by the chain so far
    bool reached = false;
    for (const Barrier* b : barriers) {
      if (b->before <= after || b->before > upto) continue;
      if (b->src_stages & ordered) {
        ordered |= b->dst_stages;
        reached |= (b->dst_stages & to) == to;
      }
    }
    return reached;
  }

  std::string layout_and_hazards(int r, const PlanResource& res, bool image, const std::vector<Use>& list,
                                 const std::vector<const Barrier*>& own) const {

    // Layouts: walk the resource's barriers and accesses in order.
    Layout layout = image ? Layout::undefined : Layout::none;
    if (res.desc.history_of >= 0 && !uses_[res.desc.history_of].empty()) layout = uses_[res.desc.history_of].back().layout;
    size_t next = 0;
    for (const Use& u : list) {
      while (next < own.size() && own[next]->before <= u.pos) {
        if (own[next]->old_layout != layout && !(own[next]->old_layout == Layout::undefined && next == 0))
          return name(r) + ": barrier's old layout does not match";
        layout = own[next]->new_layout;
        ++next;
      }
      if (image && layout != u.layout) return name(r) + " is accessed in the wrong layout at pass " + std::to_string(u.pos);
    }
    if (next != own.size()) return name(r) + " has a barrier after its last use";

    // Hazards between accesses of this resource: every earlier access that conflicts.
    for (size_t j = 1; j < list.size(); ++j)
      for (size_t i = j; i-- > 0;) {
        const Use &a = list[i], &b = list[j];
        if (!(a.writes || b.writes || a.layout != b.layout)) continue;
        if (!chained(own, a.pos, b.pos, a.stages, b.stages))
          return name(r) + ": pass " + std::to_string(b.pos) + " is not ordered after pass " + std::to_string(a.pos);
        if (a.writes) {  // the write must be made available by a barrier of this resource
          bool available = false;
          for (const Barrier* x : own)
            available |= x->before > a.pos && x->before <= b.pos && (x->src_access & a.access) != 0;
          if (!available) return name(r) + ": the write at pass " + std::to_string(a.pos) + " is never made available";
        }
        if (a.writes) break;  // earlier accesses are ordered before this write already
      }

    // The first access waits for the previous holders of its bytes.
    const Use& first = list.front();
    std::vector<int> before_first = res.placement.predecessors;
    if (res.desc.history_of < 0)
      for (size_t q = 0; q < plan_.resources.size(); ++q)
        if (plan_.resources[q].desc.history_of == r) before_first.push_back(static_cast<int>(q));
    for (int p : before_first) {
      if (uses_[p].empty()) continue;
      const Use& last = uses_[p].back();
      // Across the frame boundary for history pairs; within the frame for aliases.
      int after = plan_.resources[p].desc.history_of == r ? -1 : last.pos;
      if (!chained(own, after, first.pos, last.stages, first.stages))
        return name(r) + " takes over bytes without waiting for " + name(p);
    }
    if (res.desc.history_of >= 0 && !uses_[res.desc.history_of].empty()) {
      const Use& last = uses_[res.desc.history_of].back();
      if ((last.writes || first.writes || last.layout != first.layout) && !chained(own, -1, first.pos, last.stages, first.stages))
        return name(r) + " is read before last frame's access to it is ordered";
    }
    return {};
  }
};

void check_plan(const Plan& plan, const std::string& what) {
  Checker checker(plan);
  ASSERT_EQ(checker.check(plan.barriers), "") << what;
  std::vector<std::vector<const Barrier*>> own(plan.resources.size());
  for (const Barrier& b : plan.barriers) own[b.resource].push_back(&b);
  for (const Barrier& b : plan.barriers) {
    std::vector<const Barrier*> fewer = own[b.resource];
    std::erase(fewer, &b);
    EXPECT_NE(checker.check_resource(b.resource, fewer), "") << what << ": the barrier before pass " << plan.passes[b.before].name << " for "
                                        << plan.resources[b.resource].desc.name << " (" << barrier_reason_name(b.reason)
                                        << ") is redundant";
  }
}

TEST(PlanBarrierChecker, Examples) {
  for (const auto& file : example_files())
    for (const auto& scene : scene_files()) {
      CompileOptions options;
      options.scene = load_scene(scene);
      check_plan(compile_or_throw(load_example(file), builtin_registry(), options), file + " " + scene);
    }
}

TEST(PlanBarrierChecker, ThousandRandomGraphs) {
  size_t barriers = 0;
  for (const DagCase& c : dag_cases(1000)) {
    Plan plan = compile_or_throw(make_random_dag(c.dag), synthetic_registry(), c.options);
    barriers += plan.barriers.size();
    check_plan(plan, "nodes " + std::to_string(c.dag.nodes) + " seed " + std::to_string(c.dag.seed));
    if (testing::Test::HasFailure()) return;
  }
  EXPECT_GT(barriers, 10000u);
}

}  // namespace
}  // namespace lg::test

namespace lg::test {
namespace {

// The checker must notice broken synchronization, or its passing means nothing.
TEST(PlanBarrierChecker, NoticesWrongStagesAndLayouts) {
  Plan plan = compile_or_throw(load_example("examples/default.json"), builtin_registry());
  Checker checker(plan);
  for (size_t k = 0; k < plan.barriers.size(); ++k) {
    std::vector<Barrier> broken = plan.barriers;
    if (broken[k].src_stages != 0) {
      broken[k].src_stages = 0;
      EXPECT_NE(checker.check(broken), "") << "src stages of barrier " << k;
    }
    broken = plan.barriers;
    if (broken[k].new_layout != Layout::none) {
      broken[k].new_layout = broken[k].new_layout == Layout::general ? Layout::read_only : Layout::general;
      EXPECT_NE(checker.check(broken), "") << "new layout of barrier " << k;
    }
  }
}

}  // namespace
}  // namespace lg::test
