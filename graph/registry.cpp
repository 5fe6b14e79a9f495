#include "graph/registry.h"

#include <algorithm>

#include "graph/schema_reader.h"
#include "graph/spelling.h"

namespace lg {

bool Registry::add_schema(std::string_view json_text, Diagnostics& diagnostics) {
  auto schema = read_node_schema(json_text, diagnostics);
  if (!schema) return false;
  if (schemas_.contains(schema->type)) {
    diagnostics.error({}, "/type", "node type '" + schema->type + "' is registered twice");
    return false;
  }
  std::string type = schema->type;
  schemas_.emplace(std::move(type), std::make_unique<NodeSchema>(std::move(*schema)));
  return true;
}

const NodeSchema* Registry::find(std::string_view type) const {
  auto it = schemas_.find(type);
  return it == schemas_.end() ? nullptr : it->second.get();
}

std::vector<const NodeSchema*> Registry::all() const {
  std::vector<const NodeSchema*> out;
  for (const auto& [_, schema] : schemas_) out.push_back(schema.get());
  return out;
}

std::string Registry::closest_type(std::string_view type) const {
  std::vector<std::string> names;
  for (const auto& [name, _] : schemas_) names.push_back(name);
  return closest_name(type, names);
}

}  // namespace lg
