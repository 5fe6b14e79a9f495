// The schemas of every node folder under nodes/, compiled into the binary, and a registry
// filled with them. Links no Vulkan: the CLI's compile and validate commands and the graph
// tests use it alone.
#pragma once

#include <span>

#include "graph/embedded_file.h"
#include "graph/registry.h"

namespace lg {

std::span<const EmbeddedFile> embedded_node_schemas();

// A registry holding every built-in node schema. A broken schema is a build defect: it is
// reported on stderr and the process exits.
const Registry& builtin_registry();

}  // namespace lg
