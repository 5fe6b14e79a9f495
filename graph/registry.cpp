#include "graph/registry.h"

#include <algorithm>

#include "graph/schema_reader.h"

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

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string closest_name(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace lg
