// A file compiled into the binary (node schemas, the default graph): its source-relative path
// and its text. cmake/EmbedFiles.cmake generates the tables.
#pragma once

#include <span>
#include <string_view>

namespace lg {

struct EmbeddedFile {
  std::string_view path;
  std::string_view text;
};

}  // namespace lg
