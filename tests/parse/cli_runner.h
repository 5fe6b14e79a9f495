// Runs the built `lumagraph` as a process from the source root (where ctest runs the tests),
// the way users and scripts run it, capturing its exit status, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "tests/parse/parse_test_support.h"

namespace lg::parse_test {

struct Outcome {
  int status = -1;  // the exit status, or -1 when the process did not exit normally
  std::string out, err;
};

inline bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs `lumagraph ARGS...` from the source root (where ctest runs the tests), with `variable`
// (NAME=value) added to its environment when given.
inline Outcome lumagraph(const std::vector<std::string>& args, const std::string& variable = "") {
  TempDir dir;
  std::string command =
      (variable.empty() ? "" : "env " + shell_quote(variable) + " ") + shell_quote(LUMAGRAPH_BINARY_DIR "/lumagraph");
  for (const auto& a : args) command += " " + shell_quote(a);
  command += " >" + shell_quote(dir.file("out")) + " 2>" + shell_quote(dir.file("err")) + " </dev/null";
  int raw = std::system(command.c_str());
  Outcome r;
  if (raw != -1 && WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  r.out = read_text(dir.file("out"));
  r.err = read_text(dir.file("err"));
  return r;
}

}  // namespace lg::parse_test
