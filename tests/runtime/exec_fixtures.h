// What the executor tests share: small node schemas (fill an image from a param, add to an
// image read through a sampler, accumulate through a history input, a static bake, two passes
// through an internal resource, a buffer writer, a pass only
// scenes with area lights keep, a rasterizer of the scene's first mesh, an output
// node), kernels for them made of one
// tiny compute dispatch or draw per pass, and compiling a graph text against them for a device.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/plan.h"
#include "graph/scene_summary.h"
#include "runtime/exec/node_kernel.h"

namespace lg {
class Context;
}

namespace lg::test {

// One dispatch: writes `target` from `source` plus (add, 0, 0, 0) (the node's "add" param where
// it has one), or, without a source, fills
// it with (param "value", x, y, 1); a buffer target gets (i, param "value", 0, 1) per vec4.
struct TestStep {
  std::string pass;
  std::string source;
  std::string target;
  float add = 0;
};

// Kernels for every test schema; `calls` counts the passes each type recorded.
struct TestKernels {
  KernelRegistry registry;
  std::shared_ptr<std::map<std::string, int>> calls = std::make_shared<std::map<std::string, int>>();
};
TestKernels test_kernels();

// Compiles `graph_json` against the test schemas for `context`'s device, aliasing on or off.
Plan compile_test_graph(const Context& context, std::string_view graph_json, bool alias = true,
                        FrameSize frame = {40, 24}, const SceneSummary& scene = default_scene_summary());

}  // namespace lg::test
