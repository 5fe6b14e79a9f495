#include "cli/validation_report.h"

#include <cstdio>

namespace lg::cli {

void print_validation(const char* command, Context& context, size_t& count) {
  for (const ValidationMessage& m : context.take_validation_messages()) {
    std::fprintf(stderr, "lumagraph %s: validation: [%s] %s\n", command, m.id.c_str(), m.text.c_str());
    ++count;
  }
}

}  // namespace lg::cli
