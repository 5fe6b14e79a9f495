// Writing a whole bake (a single run or a merge): the .lgbake file itself, and beside it the
// files people and tools open: texel bakes NAME.png (k_A in grey) and NAME.exr (RGB: the bent
// normal, A: k_A), volume bakes NAME.vti (VTK XML image data with point arrays visibility,
// bent_normal and valid, for ParaView and the inspector), NAME being the .lgbake path without
// its extension.
#pragma once

#include <string>
#include <vector>

#include "nodes/occlusion/bake/bake_file.h"

namespace lg {

// VTK XML ImageData, raw appended little-endian Float32 arrays with UInt64 block headers.
std::string encode_vti(const BakeFile& volume);

// Writes `path` and its side files; returns every path written. Throws BakeFileError (or
// ImageFileError from the image writer) naming the file that failed.
std::vector<std::string> write_bake_outputs(const std::string& path, const BakeFile& file);

}  // namespace lg
