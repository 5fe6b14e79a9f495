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
      else if (k + 1 < argv.size())
        value = argv[++k];
      else {
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

}  // namespace lg::cli
