// Prints the validation messages a command's device gathered since the last call.
#pragma once

#include <cstddef>

#include "runtime/gpu/context.h"

namespace lg::cli {

// "lumagraph COMMAND: validation: [id] text" on stderr for each; adds their number to `count`.
void print_validation(const char* command, Context& context, size_t& count);

}  // namespace lg::cli
