// A JSON value that remembers where it came from (line and column) and, for numbers, the exact
// text it was written as, so that graph files round-trip losslessly and every error can point
// at its source. Objects keep their key order.
#pragma once

#include <cstdint>
#include <new>
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

  JsonValue() : text_() {}
  JsonValue(bool b) : kind_(Kind::boolean), bool_(b), text_() {}
  JsonValue(double n) : kind_(Kind::number), number_(n), text_() {}
  JsonValue(int n) : kind_(Kind::number), number_(n), text_() {}
  JsonValue(int64_t n) : kind_(Kind::number), number_(static_cast<double>(n)), text_() {}
  JsonValue(uint64_t n) : kind_(Kind::number), number_(static_cast<double>(n)), text_() {}
  JsonValue(std::string s) : kind_(Kind::string), text_(std::move(s)) {}
  JsonValue(const char* s) : kind_(Kind::string), text_(s) {}
  JsonValue(const JsonValue& other);
  JsonValue(JsonValue&& other) noexcept
      : kind_(other.kind_), bool_(other.bool_), pos_(other.pos_), number_(other.number_) {
    if (is_array())
      new (&items_) std::vector<JsonValue>(std::move(other.items_));
    else if (is_object())
      new (&members_) std::vector<Member>(std::move(other.members_));
    else
      new (&text_) std::string(std::move(other.text_));
  }
  JsonValue& operator=(const JsonValue& other);
  JsonValue& operator=(JsonValue&& other) noexcept;
  ~JsonValue() { destroy(); }
  static JsonValue array() { return JsonValue(Kind::array); }
  static JsonValue object() { return JsonValue(Kind::object); }
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
  const std::string& as_string() const { return is_container() ? no_text() : text_; }
  // The source text of a number, or empty when it was made in code.
  const std::string& number_text() const { return as_string(); }

  // Empty for values that are not arrays (objects). What a caller adds to that empty list is
  // dropped, as it would not be written out: the value keeps its kind.
  const std::vector<JsonValue>& items() const { return is_array() ? items_ : no_items(); }
  std::vector<JsonValue>& items() { return is_array() ? items_ : scratch_items(); }
  const std::vector<Member>& members() const { return is_object() ? members_ : no_members(); }
  std::vector<Member>& members() { return is_object() ? members_ : scratch_members(); }
  size_t size() const { return is_array() ? items_.size() : is_object() ? members_.size() : 0; }

  // Object access: nullptr when the key is absent (or this is not an object).
  const JsonValue* find(std::string_view key) const;
  JsonValue& set(std::string key, JsonValue value);  // replaces or appends; a non-object becomes one
  JsonValue& push(JsonValue value);                  // a non-array becomes one

  SourcePos pos() const { return pos_; }
  void set_pos(SourcePos p) { pos_ = p; }

  // Structural equality; numbers compare by value, positions are ignored.
  friend bool operator==(const JsonValue& a, const JsonValue& b);

  static const char* kind_name(Kind k);

 private:
  Kind kind_ = Kind::null;
  bool bool_ = false;
  SourcePos pos_;
  double number_ = 0;
  // One of the three is alive, by kind: items_ for arrays, members_ for objects, text_ for
  // the rest (a string's text, a number's source text, empty for null and booleans). Graphs
  // and plans hold thousands of values: 56 bytes each rather than 104 for all three.
  union {
    std::string text_;
    std::vector<JsonValue> items_;
    std::vector<Member> members_;
  };

  // An empty value of `kind`. Inline, with destroy(): plans and graphs make and drop
  // thousands of values, most of them empty objects (nodes without params).
  explicit JsonValue(Kind kind) : kind_(kind) { construct_empty(); }
  void construct_empty() {
    if (is_array())
      new (&items_) std::vector<JsonValue>();
    else if (is_object())
      new (&members_) std::vector<Member>();
    else
      new (&text_) std::string();
  }
  void destroy() {
    if (is_array())
      items_.~vector();
    else if (is_object())
      members_.~vector();
    else
      text_.~basic_string();
  }

  bool is_container() const { return is_array() || is_object(); }
  void become(Kind kind);  // an empty value of `kind`, position kept
  static const std::string& no_text();
  static const std::vector<JsonValue>& no_items();
  static const std::vector<Member>& no_members();
  static std::vector<JsonValue>& scratch_items();  // emptied on each call
  static std::vector<Member>& scratch_members();
};

// A JSON pointer (RFC 6901) built up while walking a document: "/nodes/3/params/order".
std::string json_pointer_append(std::string_view base, std::string_view token);
std::string json_pointer_append(std::string_view base, size_t index);

}  // namespace lg
