// libFuzzer harness: a part file of a chunked path-tracer reference run
// (nodes/gi/path_tracer/reference_file.h) through read_reference_part() and
// merge_reference_parts(), as `lumagraph reference --merge` reads them. A bad file must be a
// ReferenceFileError naming it.
#include "fuzz/fuzz_input.h"
#include "nodes/gi/path_tracer/reference_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const lg::fuzz::InputFile file("input.part", lg::fuzz::as_text(data, size));
  try {
    const lg::ReferencePart part = lg::read_reference_part(file.path());
    (void)lg::merge_reference_parts({part}, {file.path()});
  } catch (const lg::ReferenceFileError&) {
  }
  return 0;
}
