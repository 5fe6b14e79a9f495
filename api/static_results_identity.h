// What the static results a Renderer keeps on disk (runtime/exec/static_results_store.h) depend
// on beyond the plan: the code that computes them and the files static nodes read. Here, not in
// the runtime, because only this layer knows the node shaders and schemas.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "graph/plan.h"
#include "graph/registry.h"

namespace lg {

// A hash of every node shader's SPIR-V and of the GNU build ID of the binary holding this code
// (where the linker wrote one), so a changed shader, or a rebuilt kernel that sets it up
// differently, never finds results an older build made.
uint64_t node_code_identity();

// The files `plan`'s static nodes read: the values of their path params (env.load's image),
// absolute as the plan holds them.
std::vector<std::string> static_input_files(const Plan& plan, const Registry& registry);

}  // namespace lg
