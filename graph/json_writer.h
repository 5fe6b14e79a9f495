// Writes JsonValue as text: two-space indentation, arrays of plain numbers or strings on one
// line, numbers exactly as they were read (or the shortest text that reads back the same).
#pragma once

#include <string>

#include "graph/json_value.h"

namespace lg {

std::string write_json(const JsonValue& value);
std::string write_json_compact(const JsonValue& value);
std::string json_quote(std::string_view text);

// Writes `text` to `path` atomically: a temporary file in the same folder, flushed, then renamed
// over the target, so a crash never leaves a half-written file. Returns false on failure.
bool write_file_atomically(const std::string& path, const std::string& text, std::string* error);

}  // namespace lg
