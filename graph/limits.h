// Bounds on untrusted graph and scene files (games load mods and downloads). Anything beyond
// them is rejected with an error before it can cost unbounded memory or time. Documented in
// docs/graph-format.md; change both together.
#pragma once

#include <cstddef>

namespace lg::limits {

inline constexpr size_t max_file_bytes = 32u << 20;     // 32 MiB of JSON text
inline constexpr size_t max_json_depth = 64;            // nesting of arrays and objects
inline constexpr size_t max_json_values = 1'000'000;    // values in one document
inline constexpr size_t max_array_items = 262'144;      // items in one array or object
inline constexpr size_t max_string_bytes = 65'536;      // bytes in one string
inline constexpr size_t max_nodes = 65'536;
inline constexpr size_t max_id_length = 64;             // node ids: [A-Za-z0-9_-]
inline constexpr size_t max_image_extent = 16'384;      // texels along one axis
inline constexpr size_t max_resource_bytes = 4ull << 30;

}  // namespace lg::limits
