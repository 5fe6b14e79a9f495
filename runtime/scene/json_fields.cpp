#include "runtime/scene/json_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "graph/spelling.h"

namespace lg {
namespace {

std::string found(const JsonValue& v) {
  if (v.is_number()) return "found " + format_number(v.as_number());
  return std::string("found ") + JsonValue::kind_name(v.kind());
}

std::string range_text(double min, double max) {
  return "from " + format_number(min) + " to " + format_number(max);
}

}  // namespace

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

JsonFields::JsonFields(const JsonValue& object, std::string pointer, std::string what, std::vector<std::string> keys,
                       Diagnostics& diagnostics)
    : object_(object), pointer_(std::move(pointer)), what_(std::move(what)), d_(diagnostics) {
  if (!object.is_object()) {
    d_.error(object.pos(), pointer_, "expected " + what_ + " as an object, " + found(object));
    return;
  }
  for (const auto& [key, value] : object.members()) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string message = "unknown key '" + key + "' in " + what_;
    std::string guess = closest_name(key, keys);
    if (!guess.empty()) {
      message += "; did you mean '" + guess + "'?";
    } else {
      message += "; expected";
      for (size_t k = 0; k < keys.size(); ++k) message += (k ? ", " : " ") + keys[k];
    }
    d_.error(value.pos(), json_pointer_append(pointer_, key), message);
  }
}

std::string JsonFields::pointer(std::string_view key) const {
  return json_pointer_append(pointer_, key);
}

void JsonFields::error_at(std::string_view key, const std::string& message) const {
  const JsonValue* v = get(key);
  d_.error(v ? v->pos() : object_.pos(), v ? pointer(key) : pointer_, message);
}

void JsonFields::require(std::string_view key) const {
  if (is_object() && !get(key)) d_.error(object_.pos(), pointer_, what_ + " needs '" + std::string(key) + "'");
}

void JsonFields::number(std::string_view key, float& out, double min, double max, std::string_view unit) const {
  const JsonValue* v = get(key);
  if (!v) return;
  if (!v->is_number() || !(v->as_number() >= min && v->as_number() <= max)) {
    error_at(key, "'" + std::string(key) + "' must be a number " + range_text(min, max) +
                      (unit.empty() ? "" : " (" + std::string(unit) + ")") + ", " + found(*v));
    return;
  }
  out = static_cast<float>(v->as_number());
}

void JsonFields::integer(std::string_view key, int& out, int min, int max) const {
  const JsonValue* v = get(key);
  if (!v) return;
  if (!v->is_integer() || v->as_number() < min || v->as_number() > max) {
    error_at(key, "'" + std::string(key) + "' must be a whole number " + range_text(min, max) + ", " + found(*v));
    return;
  }
  out = static_cast<int>(v->as_number());
}

void JsonFields::boolean(std::string_view key, bool& out) const {
  const JsonValue* v = get(key);
  if (!v) return;
  if (!v->is_bool()) return error_at(key, "'" + std::string(key) + "' must be true or false, " + found(*v));
  out = v->as_bool();
}

void JsonFields::string(std::string_view key, std::string& out) const {
  const JsonValue* v = get(key);
  if (!v) return;
  if (!v->is_string()) return error_at(key, "'" + std::string(key) + "' must be a string, " + found(*v));
  out = v->as_string();
}

bool JsonFields::numbers(std::string_view key, std::vector<double>& out, size_t min_count, size_t max_count, double min,
                         double max) const {
  const JsonValue* v = get(key);
  if (!v) return false;
  std::string count = min_count == max_count ? std::to_string(min_count)
                                             : std::to_string(min_count) + " or " + std::to_string(max_count);
  std::string expected = "'" + std::string(key) + "' must be an array of " + count + " numbers " + range_text(min, max);
  if (!v->is_array() || v->size() < min_count || v->size() > max_count) {
    error_at(key, expected + ", " + (v->is_array() ? "found " + std::to_string(v->size()) + " items" : found(*v)));
    return false;
  }
  out.clear();
  bool ok = true;
  for (size_t i = 0; i < v->items().size(); ++i) {
    const JsonValue& item = v->items()[i];
    if (item.is_number() && item.as_number() >= min && item.as_number() <= max) {
      out.push_back(item.as_number());
      continue;
    }
    d_.error(item.pos(), json_pointer_append(pointer(key), i), expected + ", " + found(item));
    ok = false;
  }
  return ok;
}

void JsonFields::vec3(std::string_view key, glm::vec3& out, double min, double max) const {
  std::vector<double> v;
  if (numbers(key, v, 3, 3, min, max)) out = glm::vec3(v[0], v[1], v[2]);
}

}  // namespace lg
