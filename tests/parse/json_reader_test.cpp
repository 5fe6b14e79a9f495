// The strict JSON reader: every kind of value, where each value sits (line, and column in code
// points), escapes, UTF-8 checking, each syntax error with its own message and position, and
// every limit in graph/limits.h. Graph and scene files are untrusted input, so the reader is
// the first line of defence and its positions are what every later error points with.
#include <gtest/gtest.h>

#include <cctype>
#include <cfloat>
#include <limits>
#include <string>
#include <vector>

#include "graph/json_reader.h"
#include "graph/limits.h"
#include "parse_test_support.h"

namespace lg {
namespace {

using parse_test::TempDir;

JsonValue read_ok(std::string_view text) {
  Diagnostics d;
  auto v = read_json(text, d);
  EXPECT_TRUE(v.has_value()) << d.to_string();
  EXPECT_TRUE(d.items().empty()) << d.to_string();
  return v.value_or(JsonValue{});
}

// Reads text that must fail; returns its single diagnostic (the reader stops at the first).
Diagnostic read_error(std::string_view text) {
  Diagnostics d;
  auto v = read_json(text, d);
  EXPECT_FALSE(v.has_value());
  EXPECT_EQ(d.items().size(), 1u) << d.to_string();
  return d.items().empty() ? Diagnostic{} : d.items().front();
}

TEST(ParseJson, ReadsEveryKindOfValue) {
  JsonValue v = read_ok(R"({"n": null, "t": true, "f": false, "i": -12, "d": 1.5e2, "s": "x y",
                            "a": [1, [2], {}], "o": {"k": {"deep": []}}})");
  ASSERT_TRUE(v.is_object());
  ASSERT_EQ(v.size(), 8u);
  EXPECT_TRUE(v.find("n")->is_null());
  EXPECT_TRUE(v.find("t")->is_bool());
  EXPECT_TRUE(v.find("t")->as_bool());
  EXPECT_FALSE(v.find("f")->as_bool());
  EXPECT_EQ(v.find("i")->as_number(), -12);
  EXPECT_TRUE(v.find("i")->is_integer());
  EXPECT_EQ(v.find("d")->as_number(), 150);
  EXPECT_EQ(v.find("s")->as_string(), "x y");
  const JsonValue& a = *v.find("a");
  ASSERT_TRUE(a.is_array());
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a.items()[1].items()[0].as_number(), 2);
  EXPECT_TRUE(a.items()[2].is_object());
  EXPECT_TRUE(v.find("o")->find("k")->find("deep")->is_array());
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(ParseJson, ScalarsAreValidDocumentsOnTheirOwn) {
  EXPECT_TRUE(read_ok("null").is_null());
  EXPECT_EQ(read_ok(" 42 ").as_number(), 42);
  EXPECT_EQ(read_ok("\"s\"").as_string(), "s");
  EXPECT_TRUE(read_ok("[]").is_array());
  EXPECT_TRUE(read_ok("{}").is_object());
}

TEST(ParseJson, ObjectsKeepKeyOrder) {
  // Lossless round trips need the file's order, not a sorted one.
  JsonValue v = read_ok(R"({"zeta": 1, "alpha": 2, "mid": 3})");
  ASSERT_EQ(v.members().size(), 3u);
  EXPECT_EQ(v.members()[0].first, "zeta");
  EXPECT_EQ(v.members()[1].first, "alpha");
  EXPECT_EQ(v.members()[2].first, "mid");
}

TEST(ParseJson, RecordsLineAndColumnOfNestedValues) {
  // Columns are code points: "é" is two bytes but one column, "😀" four bytes but one.
  const char* text =
      "{\n"
      "  \"a\": [1,\n"
      "        {\"b\": \"héllo\", \"c\": 2}],\n"
      "  \"é\": 3, \"😀\": [true]\n"
      "}";
  JsonValue v = read_ok(text);
  auto at = [](const JsonValue& x, uint32_t line, uint32_t column) {
    EXPECT_EQ(x.pos().line, line);
    EXPECT_EQ(x.pos().column, column);
  };
  at(v, 1, 1);
  const JsonValue& a = *v.find("a");
  at(a, 2, 8);
  at(a.items()[0], 2, 9);
  at(a.items()[1], 3, 9);
  at(*a.items()[1].find("b"), 3, 15);
  at(*a.items()[1].find("c"), 3, 29);  // 30 if "é" counted as two
  at(*v.find("é"), 4, 8);
  at(*v.find("😀"), 4, 16);
  at(v.find("😀")->items()[0], 4, 17);
}

TEST(ParseJson, TabsCountOneColumnAndCrLfEndsALine) {
  JsonValue v = read_ok("{\r\n\t\"a\":\t1,\r\n  \"b\": 2\r\n}");
  EXPECT_EQ(v.find("a")->pos().line, 2u);
  EXPECT_EQ(v.find("a")->pos().column, 7u);
  EXPECT_EQ(v.find("b")->pos().line, 3u);
  EXPECT_EQ(v.find("b")->pos().column, 8u);
}

TEST(ParseJson, DecodesEveryEscape) {
  JsonValue v = read_ok(R"(["\"\\\/\b\f\n\r\t", "\u0041\u00e9\u20AC", "\ud83d\ude00", "a\u0000b"])");
  EXPECT_EQ(v.items()[0].as_string(), "\"\\/\b\f\n\r\t");
  EXPECT_EQ(v.items()[1].as_string(), "A\xC3\xA9\xE2\x82\xAC");  // A, é, €
  EXPECT_EQ(v.items()[2].as_string(), "\xF0\x9F\x98\x80");        // U+1F600 from a surrogate pair
  EXPECT_EQ(v.items()[3].as_string(), std::string("a\0b", 3));
}

TEST(ParseJson, AcceptsEveryValidUtf8Boundary) {
  // The smallest and largest code point of each sequence length, and around the surrogates.
  for (const char* s : {"\xC2\x80", "\xDF\xBF", "\xE0\xA0\x80", "\xED\x9F\xBF", "\xEE\x80\x80", "\xEF\xBF\xBF",
                        "\xF0\x90\x80\x80", "\xF4\x8F\xBF\xBF"}) {
    SCOPED_TRACE(testing::PrintToString(std::string(s)));
    EXPECT_EQ(read_ok("\"" + std::string(s) + "\"").as_string(), s);
  }
}

TEST(ParseJson, ByteOrderMarkIsSkippedAndTakesNoColumn) {
  JsonValue v = read_ok("\xEF\xBB\xBF{\"a\": 1}");
  EXPECT_EQ(v.pos().column, 1u);
  EXPECT_EQ(v.find("a")->pos().column, 7u);
  Diagnostic d = read_error("\xEF\xBB\xBF");
  EXPECT_EQ(d.message, "the file is empty; expected a JSON value");
}

struct SyntaxCase {
  const char* name;
  std::string text;
  std::string message;  // the whole message: each kind of mistake has its own
  uint32_t line, column;
};

std::vector<SyntaxCase> syntax_cases() {
  return {
      {"empty", "", "the file is empty; expected a JSON value", 1, 1},
      {"only whitespace", " \n\t ", "the file is empty; expected a JSON value", 2, 3},
      {"truncated object", R"({"a": 1)", "expected ',' or '}' in an object, found the end of the file", 1, 8},
      {"truncated array", "[1, 2", "expected ',' or ']' in an array, found the end of the file", 1, 6},
      {"truncated before a value", R"({"a": )", "unexpected end of the file; expected a value", 1, 7},
      {"missing comma in object", R"({"a": 1 "b": 2})", "expected ',' or '}' in an object, found '\"'", 1, 9},
      {"missing comma in array", "[1 2]", "expected ',' or ']' in an array, found '2'", 1, 4},
      {"missing colon", R"({"a" 1})", "expected ':' after the key \"a\", found '1'", 1, 6},
      {"number as key", "{1: 2}", "expected a string key in double quotes, found '1'", 1, 2},
      {"unterminated string", R"({"a": "abc)", "unterminated string", 1, 7},
      {"line break in string", "[\"abc\n\"]", "unterminated string (a line break inside a string must be written \\n)", 1, 6},
      {"tab in string", "[\"a\tb\"]", "control character inside a string (escape it)", 1, 4},
      {"unterminated escape", "[\"\\", "unterminated string", 1, 2},
      {"text after the document", "{}\n}", "unexpected text after the end of the JSON document", 2, 1},
      {"two documents", "{} {}", "unexpected text after the end of the JSON document", 1, 4},
      {"trailing comma in array", "[1, 2, ]", "trailing comma before ']'", 1, 8},
      {"trailing comma in object", "{\"a\": 1,\n}", "trailing comma before '}'", 2, 1},
      {"line comment", "[1, // one\n 2]", "comments are not allowed in JSON", 1, 5},
      {"block comment first", "/* x */ {}", "comments are not allowed in JSON", 1, 1},
      {"block comment after a value", R"({"a": 1 /* x */})", "comments are not allowed in JSON", 1, 9},
      {"NaN", "[NaN]", "NaN is not valid JSON; use a finite number", 1, 2},
      {"nan", "[1, nan]", "NaN is not valid JSON; use a finite number", 1, 5},
      {"Infinity", "[Infinity]", "JSON has no infinity; use a finite number", 1, 2},
      {"-Infinity", "[0, -Infinity]", "JSON has no infinity; use a finite number", 1, 5},
      {"inf", "[inf]", "JSON has no infinity; use a finite number", 1, 2},
      {"single-quoted value", "{\"a\": 'b'}", "strings must use double quotes, not single quotes", 1, 7},
      {"single-quoted key", "{'a': 1}", "object keys must use double quotes, not single quotes", 1, 2},
      {"duplicate key", "{\n  \"a\": 1,\n  \"a\": 2\n}", "duplicate key \"a\" (first at line 2, column 3)", 3, 3},
      {"leading zero", "[01]", "numbers may not have leading zeros", 1, 2},
      {"negative leading zero", "[-01]", "numbers may not have leading zeros", 1, 2},
      {"lone minus", "[-]", "expected a digit after '-'", 1, 2},
      {"no digit after point", "[1.]", "expected a digit after the decimal point", 1, 4},
      {"no digit in exponent", "[1e+]", "expected a digit in the exponent", 1, 5},
      {"Python True", "[True]", "unknown literal 'True' (JSON spells them true, false, null)", 1, 2},
      {"Python None", "{\"a\": None}", "unknown literal 'None' (JSON spells them true, false, null)", 1, 7},
      {"bare word", "[hello]", "unknown literal 'hello'; strings need double quotes", 1, 2},
      {"leading point", "[.5]", "expected a value, found '.'", 1, 2},
      {"plus sign", "[+1]", "expected a value, found '+'", 1, 2},
      {"closing bracket first", "]", "expected a value, found ']'", 1, 1},
      // A NUL byte is not the end of the file, and a non-ASCII character is quoted whole.
      {"NUL byte", std::string("[1\0]", 4), "expected ',' or ']' in an array, found a control character", 1, 3},
      {"non-ASCII character", "[1 \xC3\xA9]", "expected ',' or ']' in an array, found '\xC3\xA9'", 1, 4},
      {"stray invalid byte", "[\xFF]", "expected a value, found a byte that is not valid UTF-8", 1, 2},
      // Escapes: errors point at the backslash (or the bad hex digit), not the string's end.
      {"invalid escape", R"(["a\qb"])", "invalid escape \\q in a string", 1, 4},
      {"short \\u escape", R"(["\u12g4"])", "expected 4 hex digits after \\u", 1, 7},
      {"lone low surrogate", R"(["\udc00"])", "unpaired UTF-16 surrogate in \\u escape", 1, 3},
      {"lone high surrogate", R"(["x\ud83d"])", "unpaired UTF-16 surrogate in \\u escape", 1, 4},
      {"high surrogate then a letter", R"(["\ud83dx"])", "unpaired UTF-16 surrogate in \\u escape", 1, 3},
      {"high surrogate then non-surrogate", R"(["\ud83d\u0041"])", "unpaired UTF-16 surrogate in \\u escape", 1, 3},
      // Invalid UTF-8 inside strings, at the offending byte; columns count code points.
      {"0xFF byte", "[\"a\xFF\"]", "invalid UTF-8 in a string", 1, 4},
      {"after a two-byte character", "[\"\xC3\xA9\xFF\"]", "invalid UTF-8 in a string", 1, 4},
      {"lone continuation byte", "[\"\x80\"]", "invalid UTF-8 in a string", 1, 3},
      {"truncated sequence", "[\"\xC3\"]", "invalid UTF-8 in a string", 1, 3},
      {"truncated at the end of the file", "[\"\xE2\x82", "invalid UTF-8 in a string", 1, 3},
      {"overlong slash", "[\"\xC0\xAF\"]", "invalid UTF-8 in a string", 1, 3},
      {"overlong three bytes", "[\"\xE0\x80\xAF\"]", "invalid UTF-8 in a string", 1, 3},
      {"overlong four bytes", "[\"\xF0\x80\x80\xAF\"]", "invalid UTF-8 in a string", 1, 3},
      {"encoded surrogate", "[\"\xED\xA0\x80\"]", "invalid UTF-8 in a string", 1, 3},
      {"past U+10FFFF", "[\"\xF4\x90\x80\x80\"]", "invalid UTF-8 in a string", 1, 3},
      {"five-byte form", "[\"\xF8\x88\x80\x80\x80\"]", "invalid UTF-8 in a string", 1, 3},
      {"invalid UTF-8 in a key", "{\"\xFF\": 1}", "invalid UTF-8 in a string", 1, 3},
  };
}

void PrintTo(const SyntaxCase& c, std::ostream* os) { *os << c.name; }

class ParseJsonSyntax : public testing::TestWithParam<SyntaxCase> {};

TEST_P(ParseJsonSyntax, ReportsTheMistakeWhereItIs) {
  const SyntaxCase& c = GetParam();
  Diagnostic d = read_error(c.text);
  EXPECT_EQ(d.message, c.message);
  EXPECT_EQ(d.pos.line, c.line) << d.to_string();
  EXPECT_EQ(d.pos.column, c.column) << d.to_string();
  EXPECT_EQ(d.pointer, "");  // syntax errors are about the text, not a value
  EXPECT_EQ(d.severity, Severity::error);
}

std::string case_name(const testing::TestParamInfo<SyntaxCase>& info) {
  std::string out;
  for (const char* p = info.param.name; *p; ++p) out += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
  return out;
}

INSTANTIATE_TEST_SUITE_P(Cases, ParseJsonSyntax, testing::ValuesIn(syntax_cases()), case_name);

// --- Numbers ---------------------------------------------------------------------------------

TEST(ParseJson, NumbersKeepTheirSourceText) {
  JsonValue v = read_ok("[1.50, 1e3, -0, 1E+2, 0.10, 12345678901234567890]");
  std::vector<std::string> texts;
  for (const auto& item : v.items()) texts.push_back(item.number_text());
  EXPECT_EQ(texts, (std::vector<std::string>{"1.50", "1e3", "-0", "1E+2", "0.10", "12345678901234567890"}));
  EXPECT_EQ(v.items()[0].as_number(), 1.5);
  EXPECT_EQ(v.items()[1].as_number(), 1000);
  EXPECT_EQ(v.items()[3].as_number(), 100);
  EXPECT_DOUBLE_EQ(v.items()[5].as_number(), 12345678901234567890.0);
}

TEST(ParseJson, NumberOverflowIsAnErrorAtTheNumber) {
  for (const char* text : {"1e999", "-1e999", "1.8e308", "123e400"}) {
    SCOPED_TRACE(text);
    Diagnostic d = read_error(std::string("{\"x\": ") + text + "}");
    EXPECT_EQ(d.message, std::string("number ") + text + " is out of range (the largest is about 1.8e308)");
    EXPECT_EQ(d.pos.line, 1u);
    EXPECT_EQ(d.pos.column, 7u);
  }
}

TEST(ParseJson, LargestDoubleStillReads) {
  EXPECT_EQ(read_ok("1.7976931348623157e308").as_number(), DBL_MAX);
  EXPECT_EQ(read_ok("-1.7976931348623157e308").as_number(), -DBL_MAX);
}

TEST(ParseJson, NumberUnderflowReadsAsTheNearestDouble) {
  // Too small for a double rounds to zero (or a denormal): close enough, and not an error.
  JsonValue tiny = read_ok("1e-999");
  EXPECT_EQ(tiny.as_number(), 0.0);
  EXPECT_EQ(tiny.number_text(), "1e-999");
  EXPECT_EQ(read_ok("-1e-999").as_number(), 0.0);
  EXPECT_EQ(read_ok("4.9406564584124654e-324").as_number(), std::numeric_limits<double>::denorm_min());
  EXPECT_GT(read_ok("2.5e-310").as_number(), 0.0);
}

// --- Limits ------------------------------------------------------------------------------------

TEST(ParseJsonLimits, NestingUpToTheLimitReadsAndOneDeeperFails) {
  const size_t n = limits::max_json_depth;
  EXPECT_TRUE(read_ok(std::string(n, '[') + std::string(n, ']')).is_array());
  Diagnostic d = read_error(std::string(n + 1, '[') + std::string(n + 1, ']'));
  EXPECT_EQ(d.message, "nesting is deeper than 64 levels");
  EXPECT_EQ(d.pos.line, 1u);
  EXPECT_EQ(d.pos.column, n + 1);  // at the bracket that goes too deep
}

TEST(ParseJsonLimits, ObjectNestingCountsToo) {
  std::string text;
  for (size_t k = 0; k <= limits::max_json_depth; ++k) text += "{\"a\":";
  text += "1" + std::string(limits::max_json_depth + 1, '}');
  Diagnostic d = read_error(text);
  EXPECT_EQ(d.message, "nesting is deeper than 64 levels");
  EXPECT_EQ(d.pos.column, 5 * limits::max_json_depth + 1);  // each level is 5 characters
}

TEST(ParseJsonLimits, DeepNestingFailsFastWithoutExhaustingTheStack) {
  // A million brackets: stopped at level 65, long before recursion could overflow the stack.
  Diagnostic d = read_error(std::string(1'000'000, '['));
  EXPECT_EQ(d.message, "nesting is deeper than 64 levels");
}

std::string zeros_array(size_t n) {
  std::string text = "[";
  for (size_t k = 0; k < n; ++k) text += k ? ",0" : "0";
  return text + "]";
}

TEST(ParseJsonLimits, ArrayItemsUpToTheLimitReadAndOneMoreFails) {
  const size_t n = limits::max_array_items;
  EXPECT_EQ(read_ok(zeros_array(n)).size(), n);
  Diagnostic d = read_error(zeros_array(n + 1));
  EXPECT_EQ(d.message, "an array has more than 262144 items");
  EXPECT_EQ(d.pos.column, 2 * n + 2);  // item k (from 0) is at column 2k + 2
}

std::string keys_object(size_t n) {
  std::string text = "{";
  for (size_t k = 0; k < n; ++k) text += (k ? ",\"k" : "\"k") + std::to_string(k) + "\":0";
  return text + "}";
}

TEST(ParseJsonLimits, ObjectKeysUpToTheLimitReadAndOneMoreFails) {
  // Duplicate detection used to be quadratic in the number of keys (this 3 MB object took
  // minutes; now well under a second). No test asserts time: a regression shows here as a
  // run that hits ctest's timeout.
  const size_t n = limits::max_array_items;
  EXPECT_EQ(read_ok(keys_object(n)).size(), n);
  std::string over = keys_object(n + 1);
  Diagnostic d = read_error(over);
  EXPECT_EQ(d.message, "an object has more than 262144 keys");
  EXPECT_EQ(d.pos.column, over.size() - 1);  // at the value of the key too many: ...:0}
}

TEST(ParseJsonLimits, ValuesUpToTheLimitReadAndOneMoreFails) {
  // Four arrays of zeros inside one: 1 + 4 + zeros values in all, exactly the limit.
  const size_t zeros = limits::max_json_values - 5;
  auto document = [&](bool one_more) {
    std::string text = "[";
    size_t left = zeros;
    for (int a = 0; a < 4; ++a) {
      size_t n = a < 3 ? zeros / 4 : left;
      left -= n;
      text += (a ? "," : "") + zeros_array(n);
    }
    return text + (one_more ? ",0]" : "]");
  };
  EXPECT_EQ(read_ok(document(false)).size(), 4u);
  std::string over = document(true);
  Diagnostic d = read_error(over);
  EXPECT_EQ(d.message, "the document has more than 1000000 values");
  EXPECT_EQ(d.pos.column, over.size() - 1);  // the extra value
}

TEST(ParseJsonLimits, StringBytesUpToTheLimitReadAndOneMoreFails) {
  const size_t n = limits::max_string_bytes;
  EXPECT_EQ(read_ok("\"" + std::string(n, 'a') + "\"").as_string().size(), n);
  Diagnostic d = read_error("[\"" + std::string(n + 1, 'a') + "\"]");
  EXPECT_EQ(d.message, "string longer than 65536 bytes");
  EXPECT_EQ(d.pos.column, 2u);  // at the string's opening quote
}

TEST(ParseJsonLimits, MultiByteCharactersCannotCarryAStringPastTheLimit) {
  // The limit is in bytes: 32,768 two-byte characters fit exactly; one more byte, however it
  // arrives (a character, a multi-byte character at the end, an escape), does not.
  std::string e_acute;
  for (size_t k = 0; k < limits::max_string_bytes / 2; ++k) e_acute += "\xC3\xA9";
  EXPECT_EQ(read_ok("\"" + e_acute + "\"").as_string().size(), limits::max_string_bytes);
  EXPECT_EQ(read_error("\"" + e_acute + "a\"").message, "string longer than 65536 bytes");
  EXPECT_EQ(read_error("\"a" + e_acute + "\"").message, "string longer than 65536 bytes");
  EXPECT_EQ(read_error("\"" + std::string(limits::max_string_bytes - 1, 'a') + "\\u00e9\"").message,
            "string longer than 65536 bytes");
  EXPECT_EQ(read_error("\"" + std::string(limits::max_string_bytes - 3, 'a') + "\\ud83d\\ude00\"").message,
            "string longer than 65536 bytes");
}

TEST(ParseJsonLimits, FileSizeUpToTheLimitReadsAndOneByteMoreFails) {
  const size_t n = limits::max_file_bytes;
  EXPECT_EQ(read_ok(std::string(n - 1, ' ') + "0").as_number(), 0);
  Diagnostic d = read_error(std::string(n + 1, ' '));
  EXPECT_EQ(d.message, "the file is 33554433 bytes; the limit is 33554432");
  EXPECT_EQ(d.pos.line, 0u);  // about the whole file, not a place in it
}

TEST(ParseJsonLimits, ReadingAFileLargerThanTheLimitStopsEarly) {
  TempDir dir;
  std::string path = dir.file("big.json");
  parse_test::write_text(path, std::string(limits::max_file_bytes + 1, ' '));
  Diagnostics d;
  EXPECT_FALSE(read_json_file(path, d));
  ASSERT_EQ(d.items().size(), 1u) << d.to_string();
  EXPECT_EQ(d.items()[0].message, "the file is larger than the limit of 33554432 bytes");
}

TEST(ParseJson, ReadsAFileAndReportsOneThatIsMissing) {
  TempDir dir;
  std::string path = dir.file("a.json");
  parse_test::write_text(path, "{\"a\": [1, 2]}");
  Diagnostics d;
  auto v = read_json_file(path, d);
  ASSERT_TRUE(v) << d.to_string();
  EXPECT_EQ(v->find("a")->size(), 2u);

  Diagnostics missing(dir.file("none.json"));
  EXPECT_FALSE(read_json_file(dir.file("none.json"), missing));
  ASSERT_EQ(missing.items().size(), 1u);
  EXPECT_EQ(missing.items()[0].to_string(), dir.file("none.json") + ": error: cannot open the file: No such file or directory");
}

TEST(ParseJson, DiagnosticTextNamesFileLineColumnAndPointer) {
  Diagnostic d;
  d.file = "g.json";
  d.pos = {3, 14};
  d.pointer = "/nodes/0/params/order";
  d.message = "param 'order' is bad";
  EXPECT_EQ(d.to_string(), "g.json:3:14: error: param 'order' is bad (/nodes/0/params/order)");
  d.severity = Severity::warning;
  d.pointer.clear();
  d.pos = {};
  EXPECT_EQ(d.to_string(), "g.json: warning: param 'order' is bad");
}

}  // namespace
}  // namespace lg

namespace lg {
namespace {

TEST(ParseJsonPositions, EveryLineEndingStartsALine) {
  // "\n", "\r\n" and a lone "\r" (old Mac files) each end a line.
  for (const char* newline : {"\n", "\r\n", "\r"}) {
    std::string text = std::string("{") + newline + "\"a\": 1," + newline + "  x}";
    Diagnostics d;
    EXPECT_FALSE(read_json(text, d));
    ASSERT_EQ(d.items().size(), 1u);
    EXPECT_EQ(d.items()[0].pos.line, 3u) << "newline " << (newline[0] == '\r' ? "CR" : "LF");
    EXPECT_EQ(d.items()[0].pos.column, 3u);
  }
}

}  // namespace
}  // namespace lg
