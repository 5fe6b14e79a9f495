// The set of node types a build knows, keyed by type name ("post.bloom"). Filled from schema
// JSON text; graph/ never links Vulkan, so the registry knows schemas only, not kernels.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/diagnostics.h"
#include "graph/schema.h"

namespace lg {

class Registry {
 public:
  // Parses and adds one schema; errors go to `diagnostics` (whose file names the schema).
  bool add_schema(std::string_view json_text, Diagnostics& diagnostics);

  const NodeSchema* find(std::string_view type) const;
  // Type names in alphabetical order.
  std::vector<const NodeSchema*> all() const;
  // The known type closest to a misspelt one, or empty when none is close.
  std::string closest_type(std::string_view type) const;

 private:
  std::map<std::string, std::unique_ptr<NodeSchema>, std::less<>> schemas_;
};

}  // namespace lg
