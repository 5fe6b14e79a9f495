// The path tracer's files. A whole run writes one AOV as a 32-bit float EXR and its per-pixel
// standard error beside it (FILE.exr and FILE.stderr.exr). A chunk of a run (a band of rows)
// writes a part file holding every AOV of its rows, and merging all the parts of a run gives
// the same ReferenceImage as one run, bit for bit. Part file: the line "lumagraph-reference/1",
// the line "chunk I N width W height H rows BEGIN END non_finite K", the run line (below), then
// per AOV the means and then per AOV the standard errors of the rows, 3 little-endian 32-bit
// floats a pixel.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/gi/path_tracer/path_tracer.h"

namespace lg {

// The most chunks a run splits into (`lumagraph reference --chunk I/N`); part files claiming more are refused.
inline constexpr uint32_t max_reference_chunks = 65536;

class ReferenceFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ReferencePart {
  // What must match across the parts of one run: the inputs and the options that shape it.
  std::string run;  // e.g. "scene=... graph=... spp=64 bounces=8 seed=1 cull=1"
  uint32_t chunk_index = 0, chunk_count = 1;
  ReferenceImage image;
};

// Rows of chunk `index` of `count` for an image `height` tall: even bands, the first ones a row
// longer.
void chunk_rows(uint32_t height, uint32_t index, uint32_t count, uint32_t& row_begin, uint32_t& row_end);

void write_reference_part(const std::string& path, const ReferencePart& part);  // throws ReferenceFileError
ReferencePart read_reference_part(const std::string& path);                     // throws ReferenceFileError
// Checks that the parts are every chunk of one run, once each; the whole image.
ReferenceImage merge_reference_parts(const std::vector<ReferencePart>& parts, const std::vector<std::string>& paths);

// The paths written for `out` (its .stderr.exr beside it); throws ImageFileError.
std::vector<std::string> write_reference_exr(const std::string& out, const ReferenceImage& image, ReferenceAov aov);
std::string standard_error_path(const std::string& out);

}  // namespace lg
