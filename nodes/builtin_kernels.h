// The kernels of every node folder that has one, registered by node type. Nodes without a
// kernel yet compile but cannot run: the executor refuses them by name.
#pragma once

#include "runtime/exec/node_kernel.h"

namespace lg {

const KernelRegistry& builtin_kernels();

}  // namespace lg
