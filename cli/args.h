// A small command-line parser: positional arguments, --flags and --options with a value
// (`--size 1920x1080` or `--size=1920x1080`). Unknown options are usage errors.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lg::cli {

struct ArgSpec {
  std::set<std::string> flags;       // "--json"
  std::set<std::string> options;     // "--scene" (takes a value)
  std::set<std::string> repeatable;  // options that may appear more than once
};

struct Args {
  std::vector<std::string> positional;
  std::set<std::string> flags;
  std::multimap<std::string, std::string> options;

  bool has(const std::string& flag) const { return flags.contains(flag); }
  std::optional<std::string> value(const std::string& option) const;
  std::vector<std::string> values(const std::string& option) const;
};

// An unsigned decimal integer up to `max` (no sign, nothing after it).
bool parse_unsigned(const std::string& text, uint64_t max, uint64_t& value);
// "I/N" with 0 <= I < N <= max_count: chunk I of N.
bool parse_chunk(const std::string& text, uint32_t max_count, uint32_t& index, uint32_t& count);

// Option readers for the commands that bake and trace: each leaves its output unchanged without the
// option and returns the error message for a bad value ("--rays expects a count from 1 to ...").
// `option` as a count from 1 to `max`.
std::optional<std::string> read_count(const Args& args, const std::string& option, uint64_t max, uint64_t& value);
// --seed: an integer from 0 to 2^53.
std::optional<std::string> read_seed(const Args& args, uint64_t& seed);
// --chunk I/N with N <= max_count; `chunked` becomes true when it is given.
std::optional<std::string> read_chunk(const Args& args, uint32_t max_count, uint32_t& index, uint32_t& count,
                                      bool& chunked);

// Parses argv after the command name; on a usage error returns nullopt and sets `error`.
std::optional<Args> parse_args(const std::vector<std::string>& argv, const ArgSpec& spec, std::string* error);

}  // namespace lg::cli
