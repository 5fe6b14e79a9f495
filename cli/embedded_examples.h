// The example graphs compiled into the CLI; examples/default.json is what `lumagraph compile`
// and `lumagraph render` use when no graph is named.
#pragma once

#include <span>

#include "graph/embedded_file.h"

namespace lg {

std::span<const EmbeddedFile> embedded_examples();

}  // namespace lg
