// libFuzzer harness: the editor's document loader (editor/document.h, built here without the
// rest of the editor: it needs no display), then the lossless round trip the editor promises:
// a graph it opened, written back and read again, gives the same text.
#include <cstdio>
#include <cstdlib>

#include "editor/document.h"
#include "fuzz/fuzz_input.h"
#include "graph/graph_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const lg::fuzz::InputFile file("graph.json", lg::fuzz::as_text(data, size));
  lg::editor::Document document;
  lg::Diagnostics diagnostics;
  if (!document.open(QString::fromStdString(file.path()), diagnostics)) return 0;
  const std::string written = lg::graph_to_text(document.graph());
  lg::Diagnostics again;
  const std::optional<lg::Graph> reread = lg::parse_graph_text(written, again);
  if (!reread || lg::graph_to_text(*reread) != written) {
    std::fprintf(stderr, "the graph did not survive a round trip:\n%s\n%s", written.c_str(), again.to_string().c_str());
    std::abort();
  }
  return 0;
}
