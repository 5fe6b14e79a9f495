// `lumagraph render --dump DIR`: every node output port of the last frame, one file per
// resource named after node and port — textures as EXR (cube faces and mips as separate files),
// SH coefficient and scalar buffers as JSON.
#pragma once

#include <string>

namespace lg {
class Executor;
}

namespace lg::cli {

// Throws on a file that cannot be written (naming it).
void dump_outputs(Executor& executor, const std::string& dir);

}  // namespace lg::cli
