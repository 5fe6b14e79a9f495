#include "nodes/builtin_schemas.h"

#include <cstdio>
#include <cstdlib>

namespace lg {

const Registry& builtin_registry() {
  static const Registry registry = [] {
    Registry r;
    bool ok = true;
    for (const EmbeddedFile& file : embedded_node_schemas()) {
      Diagnostics diagnostics{std::string(file.path)};
      ok &= r.add_schema(file.text, diagnostics);
      std::fputs(diagnostics.to_string().c_str(), stderr);
    }
    if (!ok) {
      std::fputs("lumagraph: the built-in node schemas above are invalid\n", stderr);
      std::exit(70);
    }
    return r;
  }();
  return registry;
}

}  // namespace lg
