// What the libFuzzer harnesses share: the fuzzer's bytes as a file on disk, for loaders that read
// by path, in a folder of this process's own (removed at exit), so that runs side by side
// (-jobs) never read each other's inputs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace lg::fuzz {

// The folder, made at the first call.
const std::string& input_folder();

// A file `name` in the folder, holding `bytes`; removed again when this goes.
class InputFile {
 public:
  InputFile(std::string_view name, std::string_view bytes);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace lg::fuzz
