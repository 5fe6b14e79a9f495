#include "graph/json_value.h"

#include <cmath>
#include <new>

namespace lg {

JsonValue::JsonValue(const JsonValue& other)
    : kind_(other.kind_), bool_(other.bool_), pos_(other.pos_), number_(other.number_) {
  if (is_array())
    new (&items_) std::vector<JsonValue>(other.items_);
  else if (is_object())
    new (&members_) std::vector<Member>(other.members_);
  else
    new (&text_) std::string(other.text_);
}

JsonValue& JsonValue::operator=(const JsonValue& other) {
  if (this != &other) *this = JsonValue(other);
  return *this;
}

JsonValue& JsonValue::operator=(JsonValue&& other) noexcept {
  if (this == &other) return *this;
  JsonValue taken(std::move(other));  // first: `other` may live inside this value
  destroy();
  new (this) JsonValue(std::move(taken));
  return *this;
}

void JsonValue::become(Kind kind) {
  destroy();
  kind_ = kind;
  bool_ = false;
  number_ = 0;
  construct_empty();
}

const std::string& JsonValue::no_text() {
  static const std::string none;
  return none;
}

const std::vector<JsonValue>& JsonValue::no_items() {
  static const std::vector<JsonValue> none;
  return none;
}

const std::vector<JsonValue::Member>& JsonValue::no_members() {
  static const std::vector<Member> none;
  return none;
}

std::vector<JsonValue>& JsonValue::scratch_items() {
  thread_local std::vector<JsonValue> scratch;
  scratch.clear();
  return scratch;
}

std::vector<JsonValue::Member>& JsonValue::scratch_members() {
  thread_local std::vector<Member> scratch;
  scratch.clear();
  return scratch;
}

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
  if (!is_object()) become(Kind::object);
  for (auto& [k, v] : members_)
    if (k == key) return v = std::move(value);
  members_.emplace_back(std::move(key), std::move(value));
  return members_.back().second;
}

JsonValue& JsonValue::push(JsonValue value) {
  if (!is_array()) become(Kind::array);
  items_.push_back(std::move(value));
  return items_.back();
}

bool operator==(const JsonValue& a, const JsonValue& b) {
  if (a.kind_ != b.kind_) return false;
  switch (a.kind_) {
    case JsonValue::Kind::null:
      return true;
    case JsonValue::Kind::boolean:
      return a.bool_ == b.bool_;
    case JsonValue::Kind::number:
      return a.number_ == b.number_;
    case JsonValue::Kind::string:
      return a.text_ == b.text_;
    case JsonValue::Kind::array:
      return a.items_ == b.items_;
    case JsonValue::Kind::object:
      return a.members_ == b.members_;
  }
  return false;
}

const char* JsonValue::kind_name(Kind k) {
  switch (k) {
    case Kind::null:
      return "null";
    case Kind::boolean:
      return "a boolean";
    case Kind::number:
      return "a number";
    case Kind::string:
      return "a string";
    case Kind::array:
      return "an array";
    case Kind::object:
      return "an object";
  }
  return "?";
}

std::string json_pointer_append(std::string_view base, std::string_view token) {
  std::string out(base);
  out += '/';
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string json_pointer_append(std::string_view base, size_t index) {
  return std::string(base) + '/' + std::to_string(index);
}

}  // namespace lg
