// libFuzzer harness: a probe bake (.lgprobes, docs/probe-format.md) through read_probe_file(),
// merge_probe_parts() and probe_grids(), as gi.irradiance_volume's `file` and the inspector
// read one. A bad file must be a BakeFileError naming it.
#include "fuzz/fuzz_input.h"
#include "nodes/gi/probes/probe_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const lg::fuzz::InputFile file("input.lgprobes", lg::fuzz::as_text(data, size));
  try {
    const lg::ProbeFile probes = lg::read_probe_file(file.path());
    (void)lg::probe_grids(lg::merge_probe_parts({probes}, {file.path()}));
  } catch (const lg::BakeFileError&) {
  }
  return 0;
}
