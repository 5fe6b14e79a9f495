// Plans on the GPU: every resource of each example plan is created at its placement in the
// plan's memory blocks, and every barrier of a first frame is recorded in schedule order;
// the validation layer must accept all of it (usages, layouts, aliasing).
#include <gtest/gtest.h>

#include <variant>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"
#include "runtime/gpu/plan_barriers.h"
#include "runtime/gpu/plan_resources.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

// Placed with the device's own sizes and alignments, as an executor compiles.
Plan compile_example(const Context& context, const std::string& path, FrameSize frame) {
  Diagnostics d;
  std::optional<Graph> graph = load_graph_file(path, d);
  if (!graph) throw std::runtime_error(d.to_string());
  CompileOptions options;
  options.frame = frame;
  options.alias = device_alias_options(context);
  CompileResult result = compile(*graph, builtin_registry(), options, d);
  if (!result.plan) throw std::runtime_error(d.to_string());
  return std::move(*result.plan);
}

// The plan's resources on the device; std::monostate for those no pass touches.
struct PlanOnDevice {
  std::vector<DeviceMemory> blocks;
  std::vector<std::variant<std::monostate, Image, Buffer>> resources;
};

// Blocks take the memory types every resource placed in them accepts.
PlanOnDevice allocate(Context& context, const Plan& plan) {
  std::vector<uint32_t> type_bits(plan.blocks.size(), ~0u);
  for (const PlanResource& r : plan.resources)
    if (r.placement.block >= 0 && r.desc.kind != ResourceKind::buffer)
      type_bits[r.placement.block] &= Image::requirements(context, image_desc(r.desc)).memoryTypeBits;
  PlanOnDevice out;
  for (size_t b = 0; b < plan.blocks.size(); ++b)
    out.blocks.emplace_back(context, plan.blocks[b].size, type_bits[b], MemoryUse::device_local, "block " + std::to_string(b));
  for (const PlanResource& r : plan.resources) {
    auto& slot = out.resources.emplace_back();
    if (r.placement.block < 0) continue;
    const DeviceMemory& block = out.blocks[r.placement.block];
    if (r.desc.kind == ResourceKind::buffer)
      slot = Buffer::placed(context, buffer_desc(r.desc), block, r.placement.offset, r.placement.size);
    else
      slot = Image::placed(context, image_desc(r.desc), block, r.placement.offset, r.placement.size);
  }
  return out;
}

class PlanTest : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(PlanTest, ResourcesFitTheirPlacementsAndBarriersValidate) {
  const Plan plan = compile_example(context(), GetParam(), {64, 48});
  PlanOnDevice device = allocate(context(), plan);

  auto add = [&](BarrierBatch& batch, const Barrier& b) {
    auto& r = device.resources.at(b.resource);
    if (auto* image = std::get_if<Image>(&r)) batch.add(b, *image);
    else if (auto* buffer = std::get_if<Buffer>(&r)) batch.add(b, *buffer);
    else ADD_FAILURE() << "barrier on unplaced resource " << plan.resources[b.resource].desc.name;
  };
  submitter().run([&](VkCommandBuffer cmd) {
    // First frame: history images start cleared, in the layout their first barrier expects.
    BarrierBatch setup;
    std::vector<bool> seen(plan.resources.size());
    for (const Barrier& b : plan.barriers) {
      if (seen[b.resource]) continue;
      seen[b.resource] = true;
      if (b.old_layout == Layout::undefined || b.old_layout == Layout::none) continue;
      add(setup, {.resource = b.resource, .dst_stages = b.src_stages, .dst_access = b.src_access,
                  .old_layout = Layout::undefined, .new_layout = b.old_layout});
    }
    setup.record(cmd);
    BarrierBatch batch;
    for (size_t i = 0; i < plan.barriers.size(); ++i) {
      add(batch, plan.barriers[i]);
      if (i + 1 == plan.barriers.size() || plan.barriers[i + 1].before != plan.barriers[i].before) batch.record(cmd);
    }
  });
}

INSTANTIATE_TEST_SUITE_P(Examples, PlanTest,
                         ::testing::Values("examples/minimal.json", "examples/default.json", "examples/post.json"),
                         [](const auto& info) {
                           std::string name = info.param.substr(9);
                           return name.substr(0, name.size() - 5);
                         });

}  // namespace
}  // namespace lg::test
