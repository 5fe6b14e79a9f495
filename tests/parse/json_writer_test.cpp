// The JSON writer: numbers come out exactly as they were read (an editor that rewrote 1.50 as
// 1.5 would make noisy diffs), what it writes reads back equal, the layout is stable, and files
// are replaced atomically so a crash never leaves half a graph behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "graph/json_reader.h"
#include "graph/json_writer.h"
#include "parse_test_support.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using parse_test::read_text;
using parse_test::TempDir;
using parse_test::write_text;

JsonValue read_ok(std::string_view text) {
  Diagnostics d;
  auto v = read_json(text, d);
  EXPECT_TRUE(v.has_value()) << d.to_string();
  return v.value_or(JsonValue{});
}

std::vector<std::string> folder_entries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ParseJsonWriter, NumbersKeepTheirSourceText) {
  const std::string text = "[1.50,1e3,-0,1E+2,0.10,12345678901234567890,-3.250e-07]";
  EXPECT_EQ(write_json_compact(read_ok(text)), text);
  EXPECT_EQ(write_json(read_ok("{\"x\": 1.50, \"y\": 1e3}")), "{\n  \"x\": 1.50,\n  \"y\": 1e3\n}\n");
}

TEST(ParseJsonWriter, NumbersMadeInCodeUseTheShortestTextThatReadsBack) {
  EXPECT_EQ(write_json_compact(JsonValue(0.1)), "0.1");
  EXPECT_EQ(write_json_compact(JsonValue(-2)), "-2");
  EXPECT_EQ(write_json_compact(JsonValue(1e300)), "1e+300");
  EXPECT_EQ(write_json_compact(JsonValue(uint64_t{1} << 53)), "9007199254740992");
  for (double x : {1.0 / 3, 2.0 / 3e-300, 6.02214076e23, std::numeric_limits<double>::denorm_min(), -0.0}) {
    SCOPED_TRACE(x);
    double back = read_ok(write_json_compact(JsonValue(x))).as_number();
    EXPECT_EQ(back, x);
    EXPECT_EQ(std::signbit(back), std::signbit(x));
  }
}

TEST(ParseJsonWriter, NonFiniteNumbersBecomeNullNotInvalidJson) {
  JsonValue v = JsonValue::array();
  v.push(JsonValue(std::nan("")));
  v.push(JsonValue(std::numeric_limits<double>::infinity()));
  EXPECT_EQ(write_json_compact(v), "[null,null]");
}

TEST(ParseJsonWriter, EscapesWhatJsonRequires) {
  EXPECT_EQ(json_quote("a\"b\\c\n\r\t\b\f\x01\x1f/\xC3\xA9"), "\"a\\\"b\\\\c\\n\\r\\t\\b\\f\\u0001\\u001f/\xC3\xA9\"");
  // And every one of them reads back to the same bytes.
  std::string all;
  for (int c = 1; c < 0x80; ++c) all += static_cast<char>(c);
  all += "\xC3\xA9\xF0\x9F\x98\x80";
  EXPECT_EQ(read_ok(json_quote(all)).as_string(), all);
}

TEST(ParseJsonWriter, PrettyLayoutIsTwoSpacesWithFlatArraysOnOneLine) {
  JsonValue v = read_ok(R"({"a": [1, 2], "b": {"c": [[1], 2]}, "d": {}, "e": [], "f": ["x", null, true]})");
  EXPECT_EQ(write_json(v),
            "{\n"
            "  \"a\": [1, 2],\n"
            "  \"b\": {\n"
            "    \"c\": [\n"
            "      [1],\n"
            "      2\n"
            "    ]\n"
            "  },\n"
            "  \"d\": {},\n"
            "  \"e\": [],\n"
            "  \"f\": [\"x\", null, true]\n"
            "}\n");
  EXPECT_EQ(write_json_compact(v), R"({"a":[1,2],"b":{"c":[[1],2]},"d":{},"e":[],"f":["x",null,true]})");
}

TEST(ParseJsonWriter, LongFlatArraysGoOnePerLine) {
  std::string sixteen = "[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15]";
  EXPECT_EQ(write_json(read_ok(sixteen)), "[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]\n");
  std::string written = write_json(read_ok("[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16]"));
  EXPECT_EQ(std::count(written.begin(), written.end(), '\n'), 19);  // [, 17 items, ]
  EXPECT_EQ(written.substr(0, 8), "[\n  0,\n ");
}

// Every JSON file the project ships, plus one with the awkward corners.
std::vector<std::string> corpus() {
  std::vector<std::string> out;
  const fs::path root = LUMAGRAPH_SOURCE_DIR;
  for (const char* dir : {"examples", "nodes"})
    for (const auto& e : fs::recursive_directory_iterator(root / dir))
      if (e.is_regular_file() && e.path().extension() == ".json") out.push_back(read_text(e.path().string()));
  return out;
}

TEST(ParseJsonWriter, ReadWriteReadGivesAnEqualValue) {
  std::vector<std::string> texts = corpus();
  ASSERT_GE(texts.size(), 15u);  // the examples and every node schema
  texts.push_back(R"({"s": "tab\t quote\" slash\\ \u00e9 \ud83d\ude00 \u0000", "n": [-0, 1e-999, 1.0e+2, 0.000001],
                      "deep": [[[[{"k": [{}, [], null, false]}]]]], "": "empty key", "é": "key"})");
  for (const std::string& text : texts) {
    JsonValue first = read_ok(text);
    for (bool pretty : {true, false}) {
      std::string written = pretty ? write_json(first) : write_json_compact(first);
      JsonValue second = read_ok(written);
      EXPECT_EQ(first, second) << written;
      // Writing again changes nothing: the text is a fixed point.
      EXPECT_EQ(pretty ? write_json(second) : write_json_compact(second), written);
    }
  }
}

TEST(ParseJsonWriter, EqualityComparesContentNotFormatting) {
  // The round-trip test relies on ==; make sure it can tell values apart.
  EXPECT_EQ(read_ok("{\"a\": [1, 2.0]}"), read_ok("{ \"a\" : [ 1.0 , 2 ] }"));
  EXPECT_NE(read_ok("{\"a\": [1, 2]}"), read_ok("{\"a\": [2, 1]}"));
  EXPECT_NE(read_ok("{\"a\": 1, \"b\": 2}"), read_ok("{\"b\": 2, \"a\": 1}"));  // order matters
  EXPECT_NE(read_ok("[\"1\"]"), read_ok("[1]"));
  EXPECT_NE(read_ok("[null]"), read_ok("[false]"));
}

TEST(ParseJsonWriter, AtomicWriteReplacesTheFileAndLeavesNoTemporary) {
  TempDir dir;
  std::string path = dir.file("graph.json");
  write_text(path, "old contents, longer than the new ones\n");
  std::string error;
  ASSERT_TRUE(write_file_atomically(path, "{}\n", &error)) << error;
  EXPECT_EQ(read_text(path), "{}\n");
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"graph.json"});
}

TEST(ParseJsonWriter, AtomicWriteCreatesAMissingFile) {
  TempDir dir;
  std::string error;
  ASSERT_TRUE(write_file_atomically(dir.file("new.json"), "[1]\n", &error)) << error;
  EXPECT_EQ(read_text(dir.file("new.json")), "[1]\n");
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"new.json"});
}

TEST(ParseJsonWriter, AtomicWriteNeverShowsAReaderAHalfWrittenFile) {
  // A reader that opened the old file keeps the old contents whole: the new file is renamed
  // over it, not written into it.
  TempDir dir;
  std::string path = dir.file("graph.json");
  write_text(path, "old\n");
  std::ifstream reader(path, std::ios::binary);
  ASSERT_TRUE(reader);
  std::string error;
  ASSERT_TRUE(write_file_atomically(path, "new\n", &error)) << error;
  std::string seen((std::istreambuf_iterator<char>(reader)), std::istreambuf_iterator<char>());
  EXPECT_EQ(seen, "old\n");
  EXPECT_EQ(read_text(path), "new\n");
}

TEST(ParseJsonWriter, AtomicWriteIntoAMissingFolderFailsWithAReason) {
  TempDir dir;
  std::string path = dir.file("no-such-folder/graph.json");
  std::string error;
  EXPECT_FALSE(write_file_atomically(path, "{}\n", &error));
  EXPECT_NE(error.find("no-such-folder"), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
  EXPECT_TRUE(folder_entries(dir.path()).empty());
}

TEST(ParseJsonWriter, FailedRenameRemovesTheTemporary) {
  // A folder where the file should go: the temporary is written, the rename fails, and the
  // temporary must not be left behind.
  TempDir dir;
  fs::create_directory(dir.path() / "graph.json");
  std::string error;
  EXPECT_FALSE(write_file_atomically(dir.file("graph.json"), "{}\n", &error));
  EXPECT_NE(error.find("cannot replace"), std::string::npos) << error;
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"graph.json"});
  EXPECT_TRUE(fs::is_directory(dir.path() / "graph.json"));
}

}  // namespace
}  // namespace lg
