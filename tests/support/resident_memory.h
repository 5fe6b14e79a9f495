// The process's resident memory from /proc/self/status, and its high-water mark reset through
// /proc/self/clear_refs (Linux 4.0 and later). Unlike a heap tracker this sees every byte the
// process touches: malloc from C libraries, mapped driver memory (lavapipe's device memory is
// host memory) and the image readers' buffers alike.
#pragma once

#include <cstdint>

namespace lg::test {

// VmRSS and VmHWM in bytes; throws std::runtime_error when /proc/self/status lacks them.
int64_t resident_bytes();
int64_t peak_resident_bytes();
// Sets the high-water mark to the current resident size; throws when the kernel refuses.
void reset_peak_resident();

}  // namespace lg::test
