// A JSON value that remembers where it came from (line and column) and, for numbers, the exact
// text it was written as, so that graph files round-trip losslessly and every error can point
// at its source. Objects keep their key order.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lg {

struct SourcePos {
  uint32_t line = 0;    // 1-based; 0 means "not from a file"
  uint32_t column = 0;  // 1-based, in characters (UTF-8 code points)
};

class JsonValue {
 public:
  enum class Kind : uint8_t { null, boolean, number, string, array, object };
  using Member = std::pair<std::string, JsonValue>;

  JsonValue() = default;
  JsonValue(bool b) : kind_(Kind::boolean), bool_(b) {}
  JsonValue(double n) : kind_(Kind::number), number_(n) {}
  JsonValue(int n) : kind_(Kind::number), number_(n) {}
  JsonValue(int64_t n) : kind_(Kind::number), number_(static_cast<double>(n)) {}
  JsonValue(uint64_t n) : kind_(Kind::number), number_(static_cast<double>(n)) {}
  JsonValue(std::string s) : kind_(Kind::string), text_(std::move(s)) {}
  JsonValue(const char* s) : kind_(Kind::string), text_(s) {}
  static JsonValue array() { JsonValue v; v.kind_ = Kind::array; return v; }
  static JsonValue object() { JsonValue v; v.kind_ = Kind::object; return v; }
  // A number together with the exact text it was written as (kept for lossless output).
  static JsonValue number_with_text(double n, std::string text);

  Kind kind() const { return kind_; }
  bool is_null() const { return kind_ == Kind::null; }
  bool is_bool() const { return kind_ == Kind::boolean; }
  bool is_number() const { return kind_ == Kind::number; }
  bool is_string() const { return kind_ == Kind::string; }
  bool is_array() const { return kind_ == Kind::array; }
  bool is_object() const { return kind_ == Kind::object; }
  bool is_integer() const;

  bool as_bool() const { return bool_; }
  double as_number() const { return number_; }
  const std::string& as_string() const { return text_; }
  // The source text of a number, or empty when it was made in code.
  const std::string& number_text() const { return text_; }

  const std::vector<JsonValue>& items() const { return items_; }
  std::vector<JsonValue>& items() { return items_; }
  const std::vector<Member>& members() const { return members_; }
  std::vector<Member>& members() { return members_; }
  size_t size() const { return is_array() ? items_.size() : members_.size(); }

  // Object access: nullptr when the key is absent (or this is not an object).
  const JsonValue* find(std::string_view key) const;
  JsonValue& set(std::string key, JsonValue value);  // replaces or appends
  JsonValue& push(JsonValue value);

  SourcePos pos() const { return pos_; }
  void set_pos(SourcePos p) { pos_ = p; }

  // Structural equality; numbers compare by value, positions are ignored.
  friend bool operator==(const JsonValue& a, const JsonValue& b);

  static const char* kind_name(Kind k);

 private:
  Kind kind_ = Kind::null;
  bool bool_ = false;
  double number_ = 0;
  std::string text_;
  std::vector<JsonValue> items_;
  std::vector<Member> members_;
  SourcePos pos_;
};

// A JSON pointer (RFC 6901) built up while walking a document: "/nodes/3/params/order".
std::string json_pointer_append(std::string_view base, std::string_view token);
std::string json_pointer_append(std::string_view base, size_t index);

}  // namespace lg
