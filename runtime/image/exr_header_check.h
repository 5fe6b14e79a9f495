// A check of an OpenEXR file's header before OpenEXR's library opens it: every attribute's declared
// size must fit in the file, names must be of a length EXR allows, and the standard types must
// declare the size their content has (channel lists included). OpenEXR 3.1 allocates and reads
// whatever size a header declares, and reads fixed-size values and channel lists by content, so
// a header whose declared sizes disagree with its content sent it to read a "size" out of another
// attribute's bytes: a 300-byte file took it seconds and gigabytes of memory to refuse (found by
// fuzz/env_image_fuzzer.cpp, docs/fuzzing.md). OpenEXR also allocates a block of scan lines (or
// a tile) of every channel on opening: a header whose blocks would take more than 64 MiB is
// refused. No valid file is refused: in one, sizes and content agree, and a 16384-pixel-wide RGBA
// float image takes 64 MiB a block at most.
#pragma once

#include <cstdint>
#include <string>

namespace lg {

// Throws ImageFileError naming `path` and the attribute when one runs past the end of the file or
// disagrees with its type, when the data window holds more than `max_pixels` pixels, or when a
// block of scan lines or a tile would take more than 64 MiB.
// Files that do not start with EXR's magic number, and headers cut short (which OpenEXR reports
// itself), pass.
void check_exr_header(const std::string& path, uint64_t max_pixels);

}  // namespace lg
