// IR of phase 6 (lower): the passes the live nodes turn into and the resources they touch,
// with sizes in texels and bytes. Later phases order the passes and place the resources.
#pragma once

#include <cstdint>
#include <memory>
#include <memory_resource>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "graph/block_cache.h"
#include "graph/json_value.h"
#include "graph/port_type.h"
#include "graph/schema.h"

namespace lg {

enum class ResourceLifetime : uint8_t {
  transient,  // lives within one frame; memory may be shared with others (aliased)
  exported,   // a result of the frame: lives to the end of the frame
  cached,     // output of a static node: kept across frames, recomputed only when its key changes
  history,    // read by the next frame through a history input: kept across frames
};
std::string_view lifetime_name(ResourceLifetime l);

// Members largest first, here and in the plan's records: no padding between them (88 bytes,
// not 96), as large graphs hold tens of thousands.
struct LoweredResource {
  std::string name;  // "bloom.color", "gbuf.gbuffer.depth", "bloom/chain", "gtao.ao@previous"
  std::string_view format;  // a PortComponent's, in the program-long table of port types
  uint64_t bytes = 0;
  int node = -1;
  uint32_t width = 1, height = 1, layers = 1, mips = 1;
  int history_of = -1;  // for a previous-frame copy: the resource written this frame
  ResourceKind kind = ResourceKind::texture2d;
  bool depth_format = false;
  ResourceLifetime lifetime = ResourceLifetime::transient;
};

struct LoweredAccess {
  int resource = -1;
  Usage usage = Usage::sampled;
  PassUse::Target target = PassUse::Target::input;  // which of the node's ports, for binding
  int port = -1;
  int component = 0;  // within a bundle port (G-buffer)
};

struct LoweredPass {
  std::string name;                          // "bloom/downsample"
  std::pmr::vector<LoweredAccess> accesses;  // in LoweredGraph::arena when lowered
  uint64_t cache_key = 0;                    // static passes only
  int node = -1;
  int pass = -1;  // index into the schema's passes
  Queue queue = Queue::compute;
  bool is_static = false;
};

struct LoweredNode {
  bool is_static = false;
  uint64_t cache_key = 0;
};

// A result of the frame a host looks up: a port the file lists in "outputs", or what an
// output node (output.display) reads. Output nodes have no passes, so only this names it.
struct LoweredOutput {
  int node = -1;               // the output node, or -1 for a port of the file's "outputs"
  std::string port;            // the port whose resources these are: "tonemap.color"
  std::vector<int> resources;  // one, or a bundle's components
};

struct LoweredGraph {
  LoweredGraph() = default;
  LoweredGraph(LoweredGraph&&) noexcept = default;
  LoweredGraph(const LoweredGraph&) = default;
  // Member by member, the arena would go before the passes that allocated from it: the old
  // graph is destroyed whole (passes, then arena) and the new one built in its place.
  LoweredGraph& operator=(LoweredGraph&& other) noexcept {
    if (this != &other) {
      this->~LoweredGraph();
      new (this) LoweredGraph(std::move(other));
    }
    return *this;
  }
  LoweredGraph& operator=(const LoweredGraph& other) { return *this = LoweredGraph(other); }

  // Holds the accesses of the passes lower() makes, back to back: one allocation for them all
  // instead of one per pass, read in order by the phases after it. Shared, so that moves and
  // copies of the graph (whose vectors allocate on their own) keep it alive. Declared first, so
  // destroyed after the passes.
  std::shared_ptr<std::pmr::monotonic_buffer_resource> arena;
  CachedVector<LoweredNode> nodes;   // one per graph node (culled ones stay empty)
  CachedVector<LoweredPass> passes;  // in a valid (topological) order
  CachedVector<LoweredResource> resources;
  std::vector<LoweredOutput> outputs;  // the file's outputs, then output nodes' inputs
  // (node, node_params) for each node of a static schema, in lowering order: what its cache key
  // covers, kept so the plan does not build the params again.
  CachedVector<std::pair<int, JsonValue>> static_params;

  // Every pass's accesses together: what later phases reserve room for.
  size_t access_count() const {
    size_t count = 0;
    for (const LoweredPass& pass : passes) count += pass.accesses.size();
    return count;
  }
};

}  // namespace lg
