// Equality of short names (node ids, port and param names: a few bytes each), compared in
// line: std::string's operator== calls memcmp, which costs more than the bytes it compares.
// The compiler looks names up thousands of times a graph.
#pragma once

#include <string_view>

namespace lg {

inline bool same_short_text(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k] != b[k]) return false;
  return true;
}

}  // namespace lg
