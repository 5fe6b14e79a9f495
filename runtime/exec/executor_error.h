// Errors of the executor: a node without a kernel, a kernel that failed (its message prefixed
// with the pass's name), a resource or output looked up under an unknown name.
#pragma once

#include <stdexcept>

namespace lg {

class ExecutorError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lg
