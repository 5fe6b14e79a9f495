// Strict checks of the geometry statements of a Wavefront OBJ file, run before tinyobjloader
// reads it (obj_import.cpp): tinyobjloader reads a malformed number ("nan", "1.0abc", a missing
// coordinate) as 0, atoi()s indices ("2x" is 2, an overflowing one is undefined), skips faces
// with fewer than 3 corners or out-of-range corners with only a warning, and clips polygons in
// time quadratic in their corners, and it reads `mtllib ../../anything`. OBJ and MTL files are
// untrusted input (games load mods), so each of these is an error here, at its line and column.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "graph/diagnostics.h"

namespace lg {

// Beyond this many corners a face is refused: tinyobjloader's ear clipping of a polygon takes
// about 8 ms at 1000 corners and 2.4 s at 16000 here, so a single long `f` line of a hostile
// file could stall a load for hours.
constexpr size_t max_obj_face_corners = 1024;
// After this many problems the check stops (with one more diagnostic that says so).
constexpr size_t max_obj_errors = 20;

// The problems of OBJ `text` (read from `path`, which the diagnostics name), in file order.
// Lines end at "\n", "\r\n" or "\r", as tinyobjloader splits them; columns count UTF-8 code
// points from 1. Checked:
//   v  x y z [w] or x y z r g b   (3, 4 or 6 numbers)
//   vn x y z                      (3 numbers)
//   vt u [v [w]]                  (1 to 3 numbers)
//   f  c1 c2 c3 ...               (3 to max_obj_face_corners corners)
// Every number must be finite and within float range ("nan", "inf", "1e39" and "1.0abc" are
// refused). A corner is `v`, `v/t`, `v//n` or `v/t/n` with integer indices, never 0. A negative
// index counts back from the last element of its kind defined before its line and may not reach
// before the first; a positive one may refer to an element defined later in the file (as
// tinyobjloader allows) but not beyond the last. A `# comment` may end a v, vn or vt line, not
// an f or mtllib line (tinyobjloader would read it as a corner or a file name). The files
// `mtllib` names must lie in the OBJ file's folder or below (contained_path.h). Other statements
// (o, g, s, usemtl, l, p, free-form geometry) are left to tinyobjloader, which ignores the ones
// it does not know.
Diagnostics check_obj_text(const std::string& path, std::string_view text);

// The problems of MTL `text`, with the same conventions. Checked, as they become the PBR
// material (mesh_import.h): Kd and Ke need r g b, each a finite number of at least 0 (tinyobjloader
// reads a lone `Kd 0.5` as red); d, Tr and Pm one number from 0 to 1; Ns one of at least 0.
// Other statements (Ka, Ks, Ni, illum, texture maps...) are left to tinyobjloader.
Diagnostics check_mtl_text(const std::string& path, std::string_view text);

}  // namespace lg
