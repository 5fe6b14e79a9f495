#include "tests/support/resident_memory.h"

#include <fstream>
#include <stdexcept>
#include <string>

namespace lg::test {
namespace {

int64_t status_kib(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field + ":", 0) == 0) return std::stoll(line.substr(field.size() + 1));  // "VmRSS:  1234 kB"
  throw std::runtime_error("/proc/self/status: no " + field + " line (not Linux?)");
}

}  // namespace

int64_t resident_bytes() {
  return status_kib("VmRSS") * 1024;
}

int64_t peak_resident_bytes() {
  return status_kib("VmHWM") * 1024;
}

void reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";  // 5: reset the peak resident set size
  clear.flush();
  if (!clear) throw std::runtime_error("/proc/self/clear_refs: cannot reset the peak resident size");
}

}  // namespace lg::test
