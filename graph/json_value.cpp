#include "graph/json_value.h"

#include <cmath>

namespace lg {

JsonValue JsonValue::number_with_text(double n, std::string text) {
  JsonValue v(n);
  v.text_ = std::move(text);
  return v;
}

bool JsonValue::is_integer() const {
  return is_number() && std::isfinite(number_) && std::floor(number_) == number_;
}

const JsonValue* JsonValue::find(std::string_view key) const {
  if (!is_object()) return nullptr;
  for (const auto& [k, v] : members_)
    if (k == key) return &v;
  return nullptr;
}

JsonValue& JsonValue::set(std::string key, JsonValue value) {
  for (auto& [k, v] : members_)
    if (k == key) return v = std::move(value);
  members_.emplace_back(std::move(key), std::move(value));
  return members_.back().second;
}

JsonValue& JsonValue::push(JsonValue value) {
  items_.push_back(std::move(value));
  return items_.back();
}

bool operator==(const JsonValue& a, const JsonValue& b) {
  if (a.kind_ != b.kind_) return false;
  switch (a.kind_) {
    case JsonValue::Kind::null: return true;
    case JsonValue::Kind::boolean: return a.bool_ == b.bool_;
    case JsonValue::Kind::number: return a.number_ == b.number_;
    case JsonValue::Kind::string: return a.text_ == b.text_;
    case JsonValue::Kind::array: return a.items_ == b.items_;
    case JsonValue::Kind::object: return a.members_ == b.members_;
  }
  return false;
}

const char* JsonValue::kind_name(Kind k) {
  switch (k) {
    case Kind::null: return "null";
    case Kind::boolean: return "a boolean";
    case Kind::number: return "a number";
    case Kind::string: return "a string";
    case Kind::array: return "an array";
    case Kind::object: return "an object";
  }
  return "?";
}

std::string json_pointer_append(std::string_view base, std::string_view token) {
  std::string out(base);
  out += '/';
  for (char c : token) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string json_pointer_append(std::string_view base, size_t index) {
  return std::string(base) + '/' + std::to_string(index);
}

}  // namespace lg
