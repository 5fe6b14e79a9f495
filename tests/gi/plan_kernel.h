// A renderer's kernel of the plan node `id`, as one of the interfaces kernels lend to whoever
// asks (CapturedCubeSource, ProbeSnapshotSource): for tests that read what a node keeps between
// frames. Throws where the plan has no such node, or its kernel lends no such interface.
#pragma once

#include <stdexcept>
#include <string>

#include "api/renderer.h"

namespace lg::test {

template <typename Interface>
Interface& kernel_of(Renderer& renderer, const std::string& id) {
  const auto& nodes = renderer.plan().nodes;
  for (size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].id == id)
      if (auto* k = dynamic_cast<Interface*>(renderer.executor().kernel(i))) return *k;
  throw std::runtime_error("no node '" + id + "' with that kernel in the plan");
}

}  // namespace lg::test
