// The one error type of scene loading: every loader (load_world.h, the importers, scene files)
// throws a SceneError that holds all the problems found, each naming its file and, for scene
// files, the line, column and JSON pointer: `world.json:12:5: error: ... (/entities/3/model)`.
#pragma once

#include <stdexcept>
#include <string>

#include "graph/diagnostics.h"

namespace lg {

class SceneError : public std::runtime_error {
 public:
  explicit SceneError(Diagnostics diagnostics);
  SceneError(const std::string& file, const std::string& message);  // one error about a whole file

  const Diagnostics& diagnostics() const { return diagnostics_; }

 private:
  Diagnostics diagnostics_;
};

}  // namespace lg
