// Whether a file a model refers to (a glTF buffer or image, an OBJ's MTL library) lies in the
// model's folder or below: downloaded models are untrusted, and `../../secret` or an absolute
// path must not make an import read arbitrary files.
#pragma once

#include <string>

namespace lg {

// The absolute, canonical folder of `file`.
std::string folder_of(const std::string& file);

// Whether `path`, resolved canonically (symbolic links followed, `..` folded), lies in `folder`
// (itself canonical, as folder_of() gives it) or below.
bool inside_folder(const std::string& path, const std::string& folder);

}  // namespace lg
