// Phase 3, validate: param values against their schema (type, range, enum, paths), link types,
// required inputs, cycles (a history input is the only legal back edge) and that something is
// asked for. Reports every problem; on success returns the nodes in a topological order that
// does not depend on the order of the file (ties broken by node id).
#pragma once

#include <optional>

#include "graph/asset_paths.h"
#include "graph/block_cache.h"
#include "graph/compiler/resolved_graph.h"
#include "graph/diagnostics.h"

namespace lg {

std::optional<CachedVector<int>> validate(const ResolvedGraph& resolved, const AssetRoots& roots,
                                          Diagnostics& diagnostics);

// The topological order as node ids.
JsonValue dump_node_order(const ResolvedGraph& resolved, const CachedVector<int>& order);

// Checks one param value against its spec; empty when valid, else what was expected.
std::string check_param_value(const ParamSpec& spec, const JsonValue& value);

}  // namespace lg
