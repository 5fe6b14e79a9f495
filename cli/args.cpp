#include "cli/args.h"

#include <cstdio>

namespace lg::cli {

std::optional<std::string> Args::value(const std::string& option) const {
  auto it = options.find(option);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> Args::values(const std::string& option) const {
  std::vector<std::string> out;
  auto [begin, end] = options.equal_range(option);
  for (auto it = begin; it != end; ++it) out.push_back(it->second);
  return out;
}

std::optional<Args> parse_args(const std::vector<std::string>& argv, const ArgSpec& spec, std::string* error) {
  Args args;
  for (size_t k = 0; k < argv.size(); ++k) {
    const std::string& arg = argv[k];
    if (arg.size() < 2 || arg.rfind("--", 0) != 0) {
      if (arg.size() > 1 && arg[0] == '-') {
        *error = "unknown option '" + arg + "'";
        return std::nullopt;
      }
      args.positional.push_back(arg);
      continue;
    }
    size_t eq = arg.find('=');
    std::string name = arg.substr(0, eq);
    if (spec.flags.contains(name)) {
      if (eq != std::string::npos) {
        *error = "'" + name + "' takes no value";
        return std::nullopt;
      }
      args.flags.insert(name);
    } else if (spec.options.contains(name)) {
      std::string value;
      if (eq != std::string::npos)
        value = arg.substr(eq + 1);
      else if (k + 1 < argv.size() && argv[k + 1].rfind("--", 0) != 0)
        value = argv[++k];
      else if (k + 1 < argv.size()) {
        // `--stats --output x.png` would take `--output` as the file and `x.png` as the graph.
        *error = "'" + name + "' needs a value, not the option '" + argv[k + 1] + "' (write " + name + "=" +
                 argv[k + 1] + " if that is the value)";
        return std::nullopt;
      } else {
        *error = "'" + name + "' needs a value";
        return std::nullopt;
      }
      if (args.options.contains(name) && !spec.repeatable.contains(name)) {
        *error = "'" + name + "' given twice";
        return std::nullopt;
      }
      args.options.emplace(name, value);
    } else {
      *error = "unknown option '" + name + "'";
      return std::nullopt;
    }
  }
  return args;
}

bool parse_unsigned(const std::string& text, uint64_t max, uint64_t& value) {
  char tail = 0;
  unsigned long long v = 0;
  if (text.empty() || text[0] == '-' || std::sscanf(text.c_str(), "%llu%c", &v, &tail) != 1 || v > max) return false;
  value = v;
  return true;
}

bool parse_chunk(const std::string& text, uint32_t max_count, uint32_t& index, uint32_t& count) {
  unsigned i = 0, n = 0;
  char tail = 0;
  if (text.empty() || text[0] == '-' || std::sscanf(text.c_str(), "%u/%u%c", &i, &n, &tail) != 2 || n == 0 || i >= n ||
      n > max_count)
    return false;
  index = i, count = n;
  return true;
}

std::optional<std::string> read_count(const Args& args, const std::string& option, uint64_t max, uint64_t& value) {
  const std::optional<std::string> text = args.value(option);
  uint64_t n = 0;
  if (!text) return std::nullopt;
  if (!parse_unsigned(*text, max, n) || n == 0)
    return option + " expects a count from 1 to " + std::to_string(max) + "; got '" + *text + "'";
  value = n;
  return std::nullopt;
}

std::optional<std::string> read_seed(const Args& args, uint64_t& seed) {
  const std::optional<std::string> text = args.value("--seed");
  if (text && !parse_unsigned(*text, uint64_t(1) << 53, seed))
    return "--seed expects an integer from 0 to 2^53; got '" + *text + "'";
  return std::nullopt;
}

std::optional<std::string> read_chunk(const Args& args, uint32_t max_count, uint32_t& index, uint32_t& count,
                                      bool& chunked) {
  const std::optional<std::string> text = args.value("--chunk");
  if (!text) return std::nullopt;
  if (!parse_chunk(*text, max_count, index, count))
    return "--chunk expects I/N with 0 <= I < N <= " + std::to_string(max_count) + "; got '" + *text + "'";
  chunked = true;
  return std::nullopt;
}

}  // namespace lg::cli
