// History inputs: the only legal back edge. gtao.ao -> gtao.history in the default example reads
// last frame's AO through a persistent previous-frame copy; the same loop into an ordinary input
// is a cycle.
#include <gtest/gtest.h>

#include "graph/plan_format.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

using test::resource_at;

TEST(CompilerHistory, AoFeedsItselfThroughAPreviousFrameCopy) {
  Plan plan = test::compile_example("examples/default.json");
  int current = resource_at(plan, "gtao.ao");
  int previous = resource_at(plan, "gtao.ao@previous");
  ASSERT_GE(current, 0);
  ASSERT_GE(previous, 0);
  const PlanResource& cur = plan.resources[current];
  const PlanResource& prev = plan.resources[previous];
  EXPECT_EQ(prev.desc.history_of, current);
  EXPECT_EQ(cur.desc.history_of, -1);
  // Both halves survive the frame, in the persistent block, in bytes of their own.
  EXPECT_EQ(cur.desc.lifetime, ResourceLifetime::history);
  EXPECT_EQ(prev.desc.lifetime, ResourceLifetime::history);
  EXPECT_EQ(cur.placement.block, 1);
  EXPECT_EQ(prev.placement.block, 1);
  EXPECT_TRUE(cur.placement.offset + cur.placement.size <= prev.placement.offset ||
              prev.placement.offset + prev.placement.size <= cur.placement.offset);
  // Same image description: the runtime swaps them each frame.
  EXPECT_EQ(prev.desc.format, cur.desc.format);
  EXPECT_EQ(prev.desc.width, cur.desc.width);
  EXPECT_EQ(prev.desc.height, cur.desc.height);
  EXPECT_EQ(prev.desc.bytes, cur.desc.bytes);

  // The denoiser reads the copy and writes the current half; ibl reads the current half.
  EXPECT_EQ(test::resource_in_slot(plan, "gtao/denoise", "in.history"), previous);
  EXPECT_EQ(test::resource_in_slot(plan, "gtao/denoise", "out.ao"), current);
  EXPECT_EQ(test::resource_in_slot(plan, "ibl/shade", "in.ao"), current);
  for (const auto& p : plan.passes)
    for (const auto& a : plan.accesses_of(p))
      if (a.resource == previous) {
        EXPECT_FALSE(usage_writes(a.usage)) << p.name << " writes last frame's AO";
      }

  // The JSON plan says which resource the copy is of.
  JsonValue json = plan_to_json(plan);
  const JsonValue* entry = nullptr;
  for (const auto& r : json.find("resources")->items())
    if (r.find("name")->as_string() == "gtao.ao@previous") entry = &r;
  ASSERT_NE(entry, nullptr);
  ASSERT_NE(entry->find("previous_frame_of"), nullptr);
  EXPECT_EQ(entry->find("previous_frame_of")->as_string(), "gtao.ao");
  EXPECT_EQ(entry->find("lifetime")->as_string(), "history");
}

TEST(CompilerHistory, TheCurrentHalfWaitsForLastFramesReadsOfItsBytes) {
  Plan plan = test::compile_example("examples/default.json");
  int current = resource_at(plan, "gtao.ao");
  int previous = resource_at(plan, "gtao.ao@previous");
  int denoise = test::pass_at(plan, "gtao/denoise");
  std::vector<const Barrier*> history;
  for (const auto& b : plan.barriers)
    if (b.reason == BarrierReason::history) history.push_back(&b);
  // gtao.ao's bytes were last frame's gtao.ao@previous, sampled by the denoiser: this frame's
  // write there waits for that read (execution only: a read has nothing to make available).
  ASSERT_EQ(history.size(), 1u) << "the copy is read in the layout its partner was last read in: no barrier";
  const Barrier& b = *history[0];
  EXPECT_EQ(b.resource, current);
  EXPECT_EQ(b.before, denoise);
  EXPECT_EQ(b.src_stages, uint32_t{stage_compute_shader});
  EXPECT_EQ(b.src_access, uint32_t{access_none});
  EXPECT_EQ(b.dst_stages, uint32_t{stage_compute_shader});
  EXPECT_EQ(b.dst_access, uint32_t{access_shader_storage_write});
  EXPECT_EQ(b.new_layout, Layout::general);
  for (const auto& other : plan.barriers) EXPECT_NE(other.resource, previous);

  // When the partner's last access of the frame is a write, the copy does need one.
  Graph g = test::load_example("examples/default.json");
  test::remove_link_to(g, "ibl.ao");
  Plan plan2 = test::compile_ok(g, builtin_registry());
  int prev2 = resource_at(plan2, "gtao.ao@previous");
  int copies = 0;
  for (const auto& b2 : plan2.barriers)
    if (b2.resource == prev2) {
      ++copies;
      EXPECT_EQ(b2.reason, BarrierReason::history);
      EXPECT_EQ(b2.src_access, uint32_t{access_shader_storage_write}) << "last frame's write must be made available";
      EXPECT_EQ(b2.old_layout, Layout::general);
      EXPECT_EQ(b2.new_layout, Layout::read_only);
    }
  EXPECT_EQ(copies, 1);
}

// The built-in schemas, except that gtao's history input is an ordinary input.
const Registry& registry_without_history_inputs() {
  static const Registry registry = [] {
    Registry r;
    for (const EmbeddedFile& file : embedded_node_schemas()) {
      std::string text(file.text);
      if (file.path.find("occlusion/gtao") != std::string_view::npos) {
        size_t at = text.find("\"history\": true");
        if (at == std::string::npos) throw std::runtime_error("gtao's schema has no history input any more");
        text.replace(at, 15, "\"history\": false");
      }
      Diagnostics d(std::string(file.path));
      if (!r.add_schema(text, d)) throw std::runtime_error(d.to_string());
    }
    return r;
  }();
  return registry;
}

TEST(CompilerHistory, TheSameLoopWithoutAHistoryInputIsACycle) {
  Graph g = test::load_example("examples/default.json");
  std::string errors = test::compile_errors(g, registry_without_history_inputs());
  EXPECT_NE(errors.find("cycle: gtao -> gtao; a loop is only allowed through a history input"), std::string::npos)
      << errors;
  // The error points at the link that closes the loop: /links/3 is gtao.ao -> gtao.history.
  EXPECT_NE(errors.find("(/links/3/to)"), std::string::npos) << errors;
}

TEST(CompilerHistory, ALongerLoopWithoutAHistoryInputIsACycle) {
  // light -> ibl.direct, and ibl's output fed back into its own direct input through tonemap is a
  // type error, so close the loop on ibl itself: ibl.color -> ibl.direct.
  Graph g = test::load_example("examples/default.json");
  test::remove_link_to(g, "ibl.direct");
  test::add_link(g, "ibl.color", "ibl.direct");
  std::string errors = test::compile_errors(g, builtin_registry());
  EXPECT_NE(errors.find("cycle: ibl -> ibl; a loop is only allowed through a history input"), std::string::npos)
      << errors;

  // Two synthetic nodes in a loop closed through y's history input: legal. (The same loop
  // without a history input is a cycle error; validate_test covers that.)
  Graph s;
  test::add_node(s, "src", "test.source");
  test::add_node(s, "x", "test.blend");
  test::add_node(s, "y", "test.temporal");
  test::add_node(s, "out", "test.sink");
  test::add_link(s, "src.out", "x.a");
  test::add_link(s, "src.out", "x.b");
  test::add_link(s, "src.out", "y.a");
  test::add_link(s, "x.out", "out.color");
  test::add_link(s, "x.out", "y.history");  // y reads last frame's x
  test::add_link(s, "y.out", "x.c");
  EXPECT_EQ(test::compile_errors(s, test::synthetic_registry()), "");
}

TEST(CompilerHistory, WithoutTheHistoryLinkThereIsNoCopyAndNoHistoryBarrier) {
  Graph plain = test::load_example("examples/default.json");
  test::remove_link_to(plain, "gtao.history");
  Plan plan = test::compile_ok(plain, builtin_registry());
  EXPECT_EQ(resource_at(plan, "gtao.ao@previous"), -1);
  EXPECT_EQ(plan.resources[resource_at(plan, "gtao.ao")].desc.lifetime, ResourceLifetime::transient);
  for (const auto& b : plan.barriers) EXPECT_NE(b.reason, BarrierReason::history);
}

}  // namespace
}  // namespace lg
