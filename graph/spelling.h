// "Did you mean" suggestions for misspelt names (node types, params, ports, keys).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lg {

// Levenshtein distance.
size_t edit_distance(std::string_view a, std::string_view b);
// The candidate closest to `word` when it is close enough to be a likely typo, else empty.
std::string closest_name(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace lg
