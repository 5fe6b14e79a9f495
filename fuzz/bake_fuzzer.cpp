// libFuzzer harness: an occlusion bake file (.lgbake, docs/bake-format.md) through
// read_bake_file(), and a whole one through merge_bake_parts() as `lumagraph bake --merge` and
// the readers of baked occlusion do; an input that starts like a PRT bake (.lgprt, docs/prt.md)
// through read_prt_file() and merge_prt_parts() as gi.prt and the merge read it. A bad file must
// be a BakeFileError naming it.
#include "fuzz/fuzz_input.h"
#include "nodes/gi/prt/prt_file.h"
#include "nodes/occlusion/bake/bake_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const lg::fuzz::InputFile file("input.lgbake", lg::fuzz::as_text(data, size));
  try {
    if (lg::is_prt_file(file.path())) {
      const lg::PrtFile prt = lg::read_prt_file(file.path());
      (void)lg::merge_prt_parts({prt}, {file.path()});
    } else {
      const lg::BakeFile bake = lg::read_bake_file(file.path());
      (void)lg::merge_bake_parts({bake}, {file.path()});
    }
  } catch (const lg::BakeFileError&) {
  }
  return 0;
}
