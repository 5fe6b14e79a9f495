#include "graph/diagnostics.h"

#include <algorithm>

namespace lg {

std::string Diagnostic::to_string() const {
  std::string out = file.empty() ? std::string("<graph>") : file;
  if (pos.line > 0) out += ':' + std::to_string(pos.line) + ':' + std::to_string(pos.column);
  out += severity == Severity::error ? ": error: " : ": warning: ";
  out += message;
  if (!pointer.empty()) out += " (" + pointer + ')';
  return out;
}

void Diagnostics::error(SourcePos pos, std::string pointer, std::string message) {
  items_.push_back({Severity::error, file_, pos, std::move(pointer), std::move(message)});
}

void Diagnostics::sort_by_position() {
  std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.column < b.pos.column;
  });
}

bool Diagnostics::has_errors() const { return error_count() > 0; }

size_t Diagnostics::error_count() const {
  size_t n = 0;
  for (const auto& d : items_) n += d.severity == Severity::error;
  return n;
}

std::string Diagnostics::to_string() const {
  std::string out;
  for (const auto& d : items_) out += d.to_string() + '\n';
  return out;
}

}  // namespace lg
