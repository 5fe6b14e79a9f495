#include "graph/json_reader.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unordered_map>

#include "graph/fault_injection.h"
#include "graph/limits.h"

namespace lg {
namespace {

struct SyntaxError : std::runtime_error {
  SourcePos pos;
  SyntaxError(SourcePos p, const std::string& m) : std::runtime_error(m), pos(p) {}
};

class Reader {
 public:
  explicit Reader(std::string_view text) : s_(text) {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // UTF-8 byte order mark
  }

  JsonValue document() {
    skip_space();
    if (at_end()) fail("the file is empty; expected a JSON value");
    JsonValue root = value(0);
    skip_space();
    if (!at_end()) fail("unexpected text after the end of the JSON document");
    return root;
  }

 private:
  std::string_view s_;
  size_t i_ = 0;
  uint32_t line_ = 1, column_ = 1;
  size_t values_ = 0;

  bool at_end() const { return i_ >= s_.size(); }
  char peek() const { return at_end() ? '\0' : s_[i_]; }
  SourcePos here() const { return {line_, column_}; }

  [[noreturn]] void fail(const std::string& message) { throw SyntaxError(here(), message); }
  [[noreturn]] void fail_at(SourcePos p, const std::string& message) {
    throw SyntaxError(p, message);
  }

  void advance() {
    unsigned char c = static_cast<unsigned char>(s_[i_++]);
    // "\n", "\r\n" and a lone "\r" (old Mac files) each end a line.
    if (c == '\n' || (c == '\r' && (at_end() || s_[i_] != '\n'))) {
      ++line_;
      column_ = 1;
    } else if ((c & 0xC0) != 0x80) {  // continuation bytes do not start a new character
      ++column_;
    }
  }

  void skip_space() {
    while (!at_end()) {
      char c = peek();
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        advance();
      } else if (c == '/' && i_ + 1 < s_.size() && (s_[i_ + 1] == '/' || s_[i_ + 1] == '*')) {
        fail("comments are not allowed in JSON");
      } else {
        break;
      }
    }
  }

  // What `c` (the character at the current position) is, for "found ..." in messages: a NUL
  // byte is not the end of the file, and a non-ASCII character is quoted whole, not as one byte.
  std::string describe(char c) const {
    if (at_end()) return "the end of the file";
    if (static_cast<unsigned char>(c) < 0x20) return "a control character";
    size_t n = utf8_length();
    if (n == 0) return "a byte that is not valid UTF-8";
    return "'" + std::string(s_.substr(i_, n)) + "'";
  }

  JsonValue value(size_t depth) {
    if (++values_ > limits::max_json_values)
      fail("the document has more than " + std::to_string(limits::max_json_values) + " values");
    SourcePos start = here();
    JsonValue v;
    switch (peek()) {
      case '{': v = object(depth); break;
      case '[': v = array(depth); break;
      case '"': v = JsonValue(string()); break;
      case '\'': fail("strings must use double quotes, not single quotes");
      case '-': case '0': case '1': case '2': case '3': case '4':
      case '5': case '6': case '7': case '8': case '9': v = number(); break;
      default: v = literal(); break;
    }
    v.set_pos(start);
    return v;
  }

  void enter(size_t depth) {
    if (depth + 1 > limits::max_json_depth)
      fail("nesting is deeper than " + std::to_string(limits::max_json_depth) + " levels");
  }

  JsonValue object(size_t depth) {
    enter(depth);
    JsonValue obj = JsonValue::object();
    std::vector<SourcePos> key_pos;
    // Key -> member index: a linear search per key made an object of many keys quadratic
    // (a 3 MB file with 262,144 keys took minutes).
    std::unordered_map<std::string, size_t> key_index;
    advance();  // '{'
    skip_space();
    if (peek() == '}') {
      advance();
      return obj;
    }
    for (;;) {
      skip_space();
      if (peek() != '"') {
        if (peek() == '}') fail("trailing comma before '}'");
        if (peek() == '\'') fail("object keys must use double quotes, not single quotes");
        fail("expected a string key in double quotes, found " + describe(peek()));
      }
      SourcePos kp = here();
      std::string key = string();
      if (auto [it, fresh] = key_index.emplace(key, obj.members().size()); !fresh)
        fail_at(kp, "duplicate key \"" + key + "\" (first at line " +
                        std::to_string(key_pos[it->second].line) + ", column " +
                        std::to_string(key_pos[it->second].column) + ")");
      skip_space();
      if (peek() != ':') fail("expected ':' after the key \"" + key + "\", found " + describe(peek()));
      advance();
      skip_space();
      if (obj.members().size() >= limits::max_array_items)
        fail("an object has more than " + std::to_string(limits::max_array_items) + " keys");
      obj.members().emplace_back(std::move(key), value(depth + 1));
      key_pos.push_back(kp);
      skip_space();
      if (peek() == ',') {
        advance();
        continue;
      }
      if (peek() == '}') {
        advance();
        return obj;
      }
      fail("expected ',' or '}' in an object, found " + describe(peek()));
    }
  }

  JsonValue array(size_t depth) {
    enter(depth);
    JsonValue arr = JsonValue::array();
    advance();  // '['
    skip_space();
    if (peek() == ']') {
      advance();
      return arr;
    }
    for (;;) {
      skip_space();
      if (peek() == ']') fail("trailing comma before ']'");
      if (arr.items().size() >= limits::max_array_items)
        fail("an array has more than " + std::to_string(limits::max_array_items) + " items");
      arr.items().push_back(value(depth + 1));
      skip_space();
      if (peek() == ',') {
        advance();
        continue;
      }
      if (peek() == ']') {
        advance();
        return arr;
      }
      fail("expected ',' or ']' in an array, found " + describe(peek()));
    }
  }

  static void append_utf8(std::string& out, uint32_t cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  uint32_t hex4() {
    uint32_t cp = 0;
    for (int k = 0; k < 4; ++k) {
      char c = peek();
      int d = (c >= '0' && c <= '9') ? c - '0'
              : (c >= 'a' && c <= 'f') ? c - 'a' + 10
              : (c >= 'A' && c <= 'F') ? c - 'A' + 10
                                       : -1;
      if (d < 0) fail("expected 4 hex digits after \\u");
      cp = cp * 16 + static_cast<uint32_t>(d);
      advance();
    }
    return cp;
  }

  // Length of a valid UTF-8 sequence starting at i_, or 0 when it is malformed (RFC 3629): a
  // bad lead or continuation byte, an overlong form (C0 AF for '/'), a UTF-16 surrogate or a
  // code point past U+10FFFF.
  size_t utf8_length() const {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(s_[i_ + k]); };
    unsigned char c = byte(0);
    size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i_ + n > s_.size()) return 0;
    for (size_t k = 1; k < n; ++k)
      if ((byte(k) & 0xC0) != 0x80) return 0;
    if (n == 2 && c < 0xC2) return 0;
    if (n == 3 && ((c == 0xE0 && byte(1) < 0xA0) || (c == 0xED && byte(1) >= 0xA0))) return 0;
    if (n == 4 && ((c == 0xF0 && byte(1) < 0x90) || c > 0xF4 || (c == 0xF4 && byte(1) >= 0x90))) return 0;
    return n;
  }

  std::string string() {
    SourcePos start = here();
    advance();  // '"'
    std::string out;
    for (;;) {
      if (at_end()) fail_at(start, "unterminated string");
      // Checked after each character or escape is appended, so a multi-byte one cannot carry
      // the string past the limit.
      if (out.size() > limits::max_string_bytes)
        fail_at(start, "string longer than " + std::to_string(limits::max_string_bytes) + " bytes");
      char c = peek();
      if (c == '"') {
        advance();
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20)
        fail(c == '\n' ? "unterminated string (a line break inside a string must be written \\n)"
                       : "control character inside a string (escape it)");
      if (c == '\\') {
        SourcePos escape = here();
        advance();
        char e = peek();
        if (at_end()) fail_at(start, "unterminated string");
        advance();
        switch (e) {
          case '"': out += '"'; break;
          case '\\': out += '\\'; break;
          case '/': out += '/'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'n': out += '\n'; break;
          case 'r': out += '\r'; break;
          case 't': out += '\t'; break;
          case 'u': {
            uint32_t cp = hex4();
            const char* unpaired = "unpaired UTF-16 surrogate in \\u escape";
            if (cp >= 0xD800 && cp <= 0xDBFF) {
              if (peek() != '\\' || i_ + 1 >= s_.size() || s_[i_ + 1] != 'u') fail_at(escape, unpaired);
              advance();
              advance();
              uint32_t lo = hex4();
              if (lo < 0xDC00 || lo > 0xDFFF) fail_at(escape, unpaired);
              cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
            } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
              fail_at(escape, unpaired);
            }
            append_utf8(out, cp);
            break;
          }
          default: fail_at(escape, std::string("invalid escape \\") + e + " in a string");
        }
        continue;
      }
      size_t n = utf8_length();
      if (n == 0) fail("invalid UTF-8 in a string");
      out.append(s_.substr(i_, n));
      for (size_t k = 0; k < n; ++k) advance();
    }
  }

  JsonValue number() {
    SourcePos start = here();
    size_t begin = i_;
    auto digits = [&] {
      size_t n = 0;
      while (peek() >= '0' && peek() <= '9') {
        advance();
        ++n;
      }
      return n;
    };
    if (peek() == '-') advance();
    if (peek() == '0') {
      advance();
      if (peek() >= '0' && peek() <= '9') fail_at(start, "numbers may not have leading zeros");
    } else if (digits() == 0) {
      if (s_.substr(i_, 8) == "Infinity") fail_at(start, "JSON has no infinity; use a finite number");
      fail_at(start, "expected a digit after '-'");
    }
    if (peek() == '.') {
      advance();
      if (digits() == 0) fail("expected a digit after the decimal point");
    }
    if (peek() == 'e' || peek() == 'E') {
      advance();
      if (peek() == '+' || peek() == '-') advance();
      if (digits() == 0) fail("expected a digit in the exponent");
    }
    std::string text(s_.substr(begin, i_ - begin));
    double v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc::result_out_of_range) {
      // from_chars leaves v alone when out of range; strtod tells overflow (inf) from
      // underflow (0 or a denormal, which is as close as a double gets).
      v = std::strtod(text.c_str(), nullptr);
      if (!std::isfinite(v)) fail_at(start, "number " + text + " is out of range (the largest is about 1.8e308)");
    }
    return JsonValue::number_with_text(v, std::move(text));
  }

  JsonValue literal() {
    SourcePos start = here();
    size_t begin = i_;
    while (!at_end() && std::isalpha(static_cast<unsigned char>(peek()))) advance();
    std::string_view word = s_.substr(begin, i_ - begin);
    if (word == "true") return JsonValue(true);
    if (word == "false") return JsonValue(false);
    if (word == "null") return JsonValue();
    if (word == "NaN" || word == "nan")
      fail_at(start, "NaN is not valid JSON; use a finite number");
    if (word == "Infinity" || word == "inf")
      fail_at(start, "JSON has no infinity; use a finite number");
    if (word == "True" || word == "False" || word == "None")
      fail_at(start, "unknown literal '" + std::string(word) + "' (JSON spells them true, false, null)");
    if (!word.empty()) fail_at(start, "unknown literal '" + std::string(word) + "'; strings need double quotes");
    if (at_end()) fail("unexpected end of the file; expected a value");
    fail("expected a value, found " + describe(peek()));
  }
};

}  // namespace

std::optional<JsonValue> read_json(std::string_view text, Diagnostics& diagnostics) {
  if (text.size() > limits::max_file_bytes) {
    diagnostics.error({}, "", "the file is " + std::to_string(text.size()) +
                                  " bytes; the limit is " + std::to_string(limits::max_file_bytes));
    return std::nullopt;
  }
  try {
    return Reader(text).document();
  } catch (const SyntaxError& e) {
    diagnostics.error(e.pos, "", e.what());
    return std::nullopt;
  }
}

std::optional<JsonValue> read_json_file(const std::string& path, Diagnostics& diagnostics) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    diagnostics.error({}, "", "this is a folder; expected a JSON file");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.error({}, "", std::string("cannot open the file: ") + std::strerror(errno));
    return std::nullopt;
  }
  std::string text;
  char buffer[1 << 16];
  while (!inject_fault(FaultSite::file_read) && (in.read(buffer, sizeof buffer) || in.gcount() > 0)) {
    text.append(buffer, static_cast<size_t>(in.gcount()));
    if (text.size() > limits::max_file_bytes) {
      diagnostics.error({}, "", "the file is larger than the limit of " +
                                    std::to_string(limits::max_file_bytes) + " bytes");
      return std::nullopt;
    }
  }
  if (in.bad() || !in.eof()) {
    diagnostics.error({}, "", "cannot read the file");
    return std::nullopt;
  }
  return read_json(text, diagnostics);
}

}  // namespace lg
