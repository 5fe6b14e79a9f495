// A check of an OpenEXR file's header before OpenImageIO opens it: every attribute's declared
// size must fit in the file. OpenEXR 3.1 allocates and reads whatever size a header declares, so
// a 300-byte file whose string attribute claimed 1 GB took it 10 s and 1.3 GB of memory to
// refuse (found by fuzz/env_image_fuzzer.cpp, docs/fuzzing.md).
#pragma once

#include <string>

namespace lg {

// Throws ImageFileError naming `path` and the attribute when one runs past the end of the file.
// Files that do not start with EXR's magic number, and headers cut short (which OpenEXR reports
// itself), pass.
void check_exr_header(const std::string& path);

}  // namespace lg
