#include "graph/schema.h"

#include "graph/short_text.h"

namespace lg {
namespace {

template <class T>
int find_named(const std::vector<T>& list, std::string_view name) {
  for (size_t k = 0; k < list.size(); ++k)
    if (same_short_text(list[k].name, name)) return static_cast<int>(k);
  return -1;
}

constexpr std::array<std::string_view, 8> usage_names = {
    "sampled",          "storage_read",     "storage_write", "storage_read_write",
    "attachment_write", "attachment_blend", "buffer_read",   "buffer_write"};

}  // namespace

std::string_view param_type_name(ParamType t) {
  constexpr std::array<std::string_view, 10> names = {"float",  "int",    "bool",   "enum",   "string",
                                                      "path",   "float2", "float3", "float4", "int2"};
  return names[static_cast<size_t>(t)];
}

size_t param_components(ParamType t) {
  switch (t) {
    case ParamType::float_:
    case ParamType::int_: return 1;
    case ParamType::float2:
    case ParamType::int2: return 2;
    case ParamType::float3: return 3;
    case ParamType::float4: return 4;
    default: return 0;
  }
}

std::string_view usage_name(Usage u) { return usage_names[static_cast<size_t>(u)]; }

std::optional<Usage> parse_usage(std::string_view name) {
  for (size_t k = 0; k < usage_names.size(); ++k)
    if (usage_names[k] == name) return static_cast<Usage>(k);
  return std::nullopt;
}

int NodeSchema::find_input(std::string_view name) const { return find_named(inputs, name); }
int NodeSchema::find_output(std::string_view name) const { return find_named(outputs, name); }
int NodeSchema::find_param(std::string_view name) const { return find_named(params, name); }

}  // namespace lg
