#include "tests/bench/bench_flags.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace lg::bench {
namespace {

// The whole of `text` as a whole number of at least `at_least`.
bool parse_count(const std::string& text, long long at_least, long long& out) {
  size_t used = 0;
  try {
    out = std::stoll(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && out >= at_least;
}

}  // namespace

void BenchFlags::text(std::string name, std::string& out) {
  flags_.push_back({std::move(name), true, [&out](const std::string& v) { return out = v, !v.empty(); }});
}

void BenchFlags::count(std::string name, uint32_t& out, uint32_t at_least) {
  flags_.push_back({std::move(name), true, [&out, at_least](const std::string& v) {
                      long long n = 0;
                      return parse_count(v, at_least, n) && n <= UINT32_MAX ? (out = uint32_t(n), true) : false;
                    }});
}

void BenchFlags::count(std::string name, int& out, int at_least) {
  flags_.push_back({std::move(name), true, [&out, at_least](const std::string& v) {
                      long long n = 0;
                      return parse_count(v, at_least, n) && n <= INT32_MAX ? (out = int(n), true) : false;
                    }});
}

void BenchFlags::size(std::string name, uint32_t& width, uint32_t& height) {
  flags_.push_back({std::move(name), true, [&width, &height](const std::string& v) {
                      char rest = 0;
                      return std::sscanf(v.c_str(), "%ux%u%c", &width, &height, &rest) == 2 && width && height;
                    }});
}

void BenchFlags::numbers(std::string name, std::vector<double>& out) {
  flags_.push_back({std::move(name), true, [&out](const std::string& v) {
                      out.clear();
                      std::istringstream list(v);
                      for (std::string item; std::getline(list, item, ',');) {
                        size_t used = 0;
                        try {
                          out.push_back(std::stod(item, &used));
                        } catch (const std::exception&) {
                          return false;
                        }
                        if (used != item.size()) return false;
                      }
                      return !out.empty();
                    }});
}

void BenchFlags::set_switch(std::string name, bool& out, bool value) {
  flags_.push_back({std::move(name), false, [&out, value](const std::string&) { return out = value, true; }});
}

std::optional<int> BenchFlags::parse(int argc, char** argv) const {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(usage_.c_str(), stdout);
      return 0;
    }
    const Flag* flag = nullptr;
    for (const Flag& f : flags_)
      if (f.name == arg) flag = &f;
    bool ok = flag != nullptr;
    if (ok && flag->takes_value)
      ok = i + 1 < argc && flag->apply(argv[++i]);
    else if (ok)
      ok = flag->apply({});
    if (!ok) {
      std::fprintf(stderr, "%s: bad or unknown option '%s'\n%s", argv[0], arg.c_str(), usage_.c_str());
      return 2;
    }
  }
  return std::nullopt;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find(',', start), text.size());
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

bool example_worlds_exist(const char* tool, const std::string& source, const std::string& worlds) {
  for (const std::string& name : split_commas(worlds))
    if (!std::filesystem::exists(source + "/examples/worlds/" + name + ".json")) {
      std::fprintf(stderr, "%s: --worlds: no world '%s' in examples/worlds/\n", tool, name.c_str());
      return false;
    }
  return true;
}

bool names_known(const char* tool, const char* flag, const std::string& names,
                 std::initializer_list<std::string_view> known) {
  for (const std::string& name : split_commas(names)) {
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string expected;
    for (auto k = known.begin(); k != known.end(); ++k)
      expected += (k == known.begin() ? "" : k + 1 == known.end() ? " or " : ", ") + std::string(*k);
    std::fprintf(stderr, "%s: %s: unknown '%s' (expected %s)\n", tool, flag, name.c_str(), expected.c_str());
    return false;
  }
  return true;
}

}  // namespace lg::bench
