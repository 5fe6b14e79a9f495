#include "runtime/scene/scene_error.h"

namespace lg {
namespace {

Diagnostics one_error(const std::string& file, const std::string& message) {
  Diagnostics d(file);
  d.error({}, "", message);
  return d;
}

std::string without_last_newline(std::string text) {
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

}  // namespace

SceneError::SceneError(Diagnostics diagnostics)
    : std::runtime_error(without_last_newline(diagnostics.to_string())), diagnostics_(std::move(diagnostics)) {}

SceneError::SceneError(const std::string& file, const std::string& message) : SceneError(one_error(file, message)) {}

}  // namespace lg
