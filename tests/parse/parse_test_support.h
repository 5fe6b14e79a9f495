// Helpers shared by the parse tests: a temporary folder that cleans up after itself, whole-file
// reads and writes, and looking a diagnostic up by its message.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "graph/diagnostics.h"

namespace lg::parse_test {

namespace fs = std::filesystem;

// A fresh folder under the system temporary folder, removed with its contents at scope exit.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "lumagraph-parse-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = fs::path(pattern);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

inline void write_text(const std::string& path, std::string_view text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The first diagnostic whose message contains `needle`, or nullptr.
inline const Diagnostic* find_message(const Diagnostics& diagnostics, std::string_view needle) {
  for (const auto& d : diagnostics.items())
    if (d.message.find(needle) != std::string::npos) return &d;
  return nullptr;
}

}  // namespace lg::parse_test
