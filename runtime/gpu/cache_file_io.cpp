#include "runtime/gpu/cache_file_io.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "graph/json_writer.h"

namespace lg {

CacheFileRead read_cache_file(const std::string& path) {
  CacheFileRead read;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return read;
  read.exists = true;
  if (!std::filesystem::is_regular_file(path, error)) {
    read.problem = "it is not a regular file";
    return read;
  }
  std::ifstream in(path, std::ios::binary);
  read.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (!in.is_open() || in.bad()) read.problem = std::string("cannot read it: ") + std::strerror(errno);
  return read;
}

std::string write_cache_file(const std::string& folder, const std::string& path, const std::string& bytes) {
  std::error_code made;
  std::filesystem::create_directories(folder, made);
  if (made) return "cannot make the folder " + folder + ": " + made.message();
  std::string error;
  if (!write_file_atomically(path, bytes, &error)) return error.empty() ? "cannot write it" : error;
  return "";
}

}  // namespace lg
