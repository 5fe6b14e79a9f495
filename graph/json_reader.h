// Strict JSON (RFC 8259) reader that records the line and column of every value and enforces
// the limits in limits.h. It stops at the first syntax error, which it reports precisely:
// NaN, comments, trailing commas, single quotes and duplicate keys each get their own message.
#pragma once

#include <optional>
#include <string_view>

#include "graph/diagnostics.h"
#include "graph/json_value.h"

namespace lg {

std::optional<JsonValue> read_json(std::string_view text, Diagnostics& diagnostics);

// Reads a whole file (bounded by limits::max_file_bytes) and parses it.
std::optional<JsonValue> read_json_file(const std::string& path, Diagnostics& diagnostics);

}  // namespace lg
