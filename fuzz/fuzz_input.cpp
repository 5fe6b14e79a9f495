#include "fuzz/fuzz_input.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace lg::fuzz {

const std::string& input_folder() {
  // Never destroyed: the exit handler that removes the folder runs after static destructors.
  static const std::string* const folder = [] {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("lumagraph-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(input_folder(), ignored);
    });
    return new std::string(dir.string());
  }();
  return *folder;
}

InputFile::InputFile(std::string_view name, std::string_view bytes)
    : path_((std::filesystem::path(input_folder()) / name).string()) {
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out.flush()) throw std::runtime_error("fuzz: cannot write " + path_);  // the machine, not the input
}

InputFile::~InputFile() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace lg::fuzz
