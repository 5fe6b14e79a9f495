// The example graphs through the executor with kernels that record nothing: over several
// frames every barrier the executor records for the real plans (history pairs, cached
// hand-offs skipped on later frames, aliasing, attachments) must satisfy the validation layer
// and synchronization validation, and each example's output is found by name.
#include <gtest/gtest.h>

#include "runtime/exec/executor.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/scene/scene_view.h"
#include "tests/runtime/example_plan.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

struct RecordsNothing final : NodeKernel {
  void record(PassContext&) override {}
};

class ExecExamplesTest : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(ExecExamplesTest, FramesValidateAndLaterFramesSkipCachedPasses) {
  KernelRegistry kernels;
  for (const NodeSchema* schema : builtin_registry().all())
    kernels.add(schema->type, [](const PlanNode&) { return std::make_unique<RecordsNothing>(); });
  Executor exec(context(), kernels, compile_example(context(), GetParam(), {64, 48}));
  GpuScene gpu_scene(context());
  SceneView scene;
  for (uint64_t frame = 0; frame < 3; ++frame) {
    FrameStats stats = exec.run_frame(scene, gpu_scene);
    ASSERT_EQ(stats.passes.size(), exec.plan().passes.size());
    for (size_t p = 0; p < stats.passes.size(); ++p)
      EXPECT_EQ(stats.passes[p].cached, frame > 0 && exec.plan().passes[p].is_static) << stats.passes[p].name;
  }
  const std::vector<std::string> outputs = exec.output_names();
  ASSERT_FALSE(outputs.empty());
  const std::string& resource = exec.output_resource(outputs.front());
  EXPECT_NE(exec.layout(resource), VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(exec.read_image(resource).size(),
            size_t{exec.image(resource).desc().width} * exec.image(resource).desc().height * 4);
}

INSTANTIATE_TEST_SUITE_P(Examples, ExecExamplesTest, ::testing::ValuesIn(example_graphs),
                         [](const auto& info) { return example_name(info.param); });

}  // namespace
}  // namespace lg::test
