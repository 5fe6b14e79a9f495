// Plans on the GPU: every resource of each example plan is created at its placement in the
// plan's memory blocks, and every barrier of a first frame is recorded in schedule order;
// the validation layer must accept all of it (usages, layouts, aliasing).
#include <gtest/gtest.h>

#include "runtime/exec/plan_memory.h"
#include "runtime/gpu/plan_barriers.h"
#include "tests/runtime/example_plan.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

class PlanTest : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(PlanTest, ResourcesFitTheirPlacementsAndBarriersValidate) {
  const Plan plan = compile_example(context(), GetParam(), {64, 48});
  PlanMemory device = allocate_plan_memory(context(), plan);

  auto add = [&](BarrierBatch& batch, const Barrier& b) {
    auto& r = device.resources.at(b.resource);
    if (auto* image = std::get_if<Image>(&r))
      batch.add(b, *image);
    else if (auto* buffer = std::get_if<Buffer>(&r))
      batch.add(b, *buffer);
    else
      ADD_FAILURE() << "barrier on unplaced resource " << plan.resources[b.resource].desc.name;
  };
  submitter().run([&](VkCommandBuffer cmd) {
    // First frame: history images start cleared, in the layout their first barrier expects.
    BarrierBatch setup;
    std::vector<bool> seen(plan.resources.size());
    for (const Barrier& b : plan.barriers) {
      if (seen[b.resource]) continue;
      seen[b.resource] = true;
      if (b.old_layout == Layout::undefined || b.old_layout == Layout::none) continue;
      add(setup, {.resource = b.resource,
                  .dst_stages = b.src_stages,
                  .dst_access = b.src_access,
                  .old_layout = Layout::undefined,
                  .new_layout = b.old_layout});
    }
    setup.record(cmd);
    BarrierBatch batch;
    for (size_t i = 0; i < plan.barriers.size(); ++i) {
      add(batch, plan.barriers[i]);
      if (i + 1 == plan.barriers.size() || plan.barriers[i + 1].before != plan.barriers[i].before) batch.record(cmd);
    }
  });
}

INSTANTIATE_TEST_SUITE_P(Examples, PlanTest, ::testing::ValuesIn(example_graphs),
                         [](const auto& info) { return example_name(info.param); });

}  // namespace
}  // namespace lg::test
