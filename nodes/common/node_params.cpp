#include "nodes/common/node_params.h"

#include <cmath>
#include <stdexcept>

namespace lg {
namespace {

const JsonValue& param(const PlanNode& node, std::string_view name, JsonValue::Kind kind) {
  const JsonValue* value = node.params.find(name);
  if (!value || value->kind() != kind)
    throw std::logic_error("node '" + node.id + "' (" + node.type + ") has no " + JsonValue::kind_name(kind) +
                           " param '" + std::string(name) + "'");
  return *value;
}

}  // namespace

double param_number(const PlanNode& node, std::string_view name) {
  return param(node, name, JsonValue::Kind::number).as_number();
}

bool param_bool(const PlanNode& node, std::string_view name) {
  return param(node, name, JsonValue::Kind::boolean).as_bool();
}

const std::string& param_string(const PlanNode& node, std::string_view name) {
  return param(node, name, JsonValue::Kind::string).as_string();
}

glm::vec3 param_float3(const PlanNode& node, std::string_view name) {
  const JsonValue& v = param(node, name, JsonValue::Kind::array);
  if (v.items().size() != 3)
    throw std::logic_error("param '" + std::string(name) + "' of node '" + node.id + "' is not a float3");
  return glm::vec3(v.items()[0].as_number(), v.items()[1].as_number(), v.items()[2].as_number());
}

int resolution_divisor(const PlanNode& node) {
  return int(std::lround(1.0 / param_number(node, "resolution_scale")));
}

}  // namespace lg
