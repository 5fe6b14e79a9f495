// Helpers of the import tests: fixture paths, writing variants of fixtures into the build
// folder, and catching the SceneError of a load.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "runtime/scene/scene_error.h"

namespace lg::test {

inline std::string fixture(const std::string& name) {
  return (std::filesystem::path(LUMAGRAPH_SOURCE_DIR "/tests/scene/data") / name).string();
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `bytes` to a file of the build folder and returns its path.
inline std::string write_variant(const std::string& name, const std::string& bytes) {
  auto dir = std::filesystem::path(LUMAGRAPH_BINARY_DIR) / "scene-test-files";
  std::filesystem::create_directories(dir);
  auto path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// `text` with its one occurrence of `from` replaced (fails the test if not exactly one).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The message of the SceneError `load` throws, or "" (with a failure) when it throws none.
inline std::string error_of(const std::function<void()>& load) {
  try {
    load();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a SceneError";
  return {};
}

}  // namespace lg::test
