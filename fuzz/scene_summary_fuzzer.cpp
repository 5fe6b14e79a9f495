// libFuzzer harness: a scene summary (`lumagraph compile --scene FILE`'s JSON, graph/
// scene_summary.h) through the JSON reader and scene_summary_from_json(). Rejections must say why.
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_input.h"
#include "graph/json_reader.h"
#include "graph/scene_summary.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lg::Diagnostics diagnostics("summary.json");
  const std::optional<lg::JsonValue> json = lg::read_json(lg::fuzz::as_text(data, size), diagnostics);
  const bool ok = json && lg::scene_summary_from_json(*json, diagnostics).has_value();
  if (ok == diagnostics.has_errors()) {
    std::fprintf(stderr, "the summary reader disagrees with its diagnostics\n%s", diagnostics.to_string().c_str());
    std::abort();
  }
  return 0;
}
