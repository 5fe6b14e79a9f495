// Synthetic graphs for compiler tests and benchmarks: a registry of small test node types that
// exercise every port kind and usage (storage, sampled, attachments, buffers, bundles, history),
// and generators for chains and random DAGs with a chosen share of dead nodes.
#pragma once

#include <cstdint>

#include "graph/graph.h"
#include "graph/registry.h"

namespace lg::test {

// The test node types ("test.source", "test.filter", ...). Built once.
const Registry& synthetic_registry();

// source -> filter -> ... -> filter -> sink: `nodes` nodes in all.
Graph make_chain(size_t nodes);

struct RandomDagOptions {
  size_t nodes = 100;
  double dead_fraction = 0.3;   // share of nodes no output depends on
  double history_fraction = 0;  // share of temporal nodes with a history back edge
  size_t window = 12;           // inputs come from the last `window` nodes: real graphs are local
  uint64_t seed = 1;
};

// A random DAG whose live part feeds one output node; dead nodes take inputs but feed nothing
// live. Deterministic for a seed.
Graph make_random_dag(const RandomDagOptions& options);

}  // namespace lg::test
