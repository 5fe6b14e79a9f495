// The command lines of the benchmark programs: `--name VALUE` flags and bare switches, each
// bound to the option it sets. An unknown flag, a missing value or one that does not parse
// prints the program's usage and fails the parse, so a mistyped run never measures defaults.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lg::bench {

class BenchFlags {
 public:
  explicit BenchFlags(std::string usage) : usage_(std::move(usage)) {}

  void text(std::string name, std::string& out);
  // A whole number of at least `at_least`.
  void count(std::string name, uint32_t& out, uint32_t at_least = 1);
  void count(std::string name, int& out, int at_least = 1);
  // WxH.
  void size(std::string name, uint32_t& width, uint32_t& height);
  // Comma-separated numbers, replacing the defaults.
  void numbers(std::string name, std::vector<double>& out);
  // Present: `out` becomes `value`.
  void set_switch(std::string name, bool& out, bool value);

  // Applies argv[1..]. Empty when the program should run; else the status to exit with: 2 after
  // printing the usage to stderr for anything it does not know or cannot parse, 0 after
  // printing it to stdout for -h or --help.
  std::optional<int> parse(int argc, char** argv) const;

 private:
  struct Flag {
    std::string name;
    bool takes_value;
    std::function<bool(const std::string&)> apply;  // false: the value does not parse
  };
  std::string usage_;
  std::vector<Flag> flags_;
};

// "a,b,c" -> {"a", "b", "c"}; "" -> {""}.
std::vector<std::string> split_commas(const std::string& text);

// Whether every name of the comma list `worlds` is a file examples/worlds/NAME.json under
// `source`; else prints "TOOL: --worlds: no world 'NAME' in examples/worlds/" and answers false.
bool example_worlds_exist(const char* tool, const std::string& source, const std::string& worlds);

// Whether every name of the comma list `names` is one of `known` (a benchmark that picks what to
// run by name would silently measure nothing for a misspelt one); else prints "TOOL: FLAG:
// unknown 'NAME' (expected a, b or c)" and answers false.
bool names_known(const char* tool, const char* flag, const std::string& names,
                 std::initializer_list<std::string_view> known);

}  // namespace lg::bench
