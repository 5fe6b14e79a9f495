// Errors and warnings about a file, printed as `file:line:col: error: message (json pointer)`.
// Every phase appends to one Diagnostics so that all the problems in a file are reported at once.
#pragma once

#include <string>
#include <vector>

#include "graph/json_value.h"

namespace lg {

enum class Severity { error, warning };

struct Diagnostic {
  Severity severity = Severity::error;
  std::string file;
  SourcePos pos;
  std::string pointer;  // JSON pointer to the offending value, empty for the whole file
  std::string message;

  std::string to_string() const;
};

class Diagnostics {
 public:
  explicit Diagnostics(std::string file = {}) : file_(std::move(file)) {}

  void error(SourcePos pos, std::string pointer, std::string message);
  void add(Diagnostic d) { items_.push_back(std::move(d)); }

  const std::string& file() const { return file_; }
  void set_file(std::string file) { file_ = std::move(file); }
  // Orders the diagnostics by line and column, as a reader goes through the file.
  void sort_by_position();
  bool has_errors() const;
  size_t error_count() const;
  const std::vector<Diagnostic>& items() const { return items_; }
  // All diagnostics, one per line, in the order they were found.
  std::string to_string() const;

 private:
  std::string file_;
  std::vector<Diagnostic> items_;
};

}  // namespace lg
