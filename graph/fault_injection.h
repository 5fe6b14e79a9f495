// A test hook that makes one call at a failure site fail, so tests can check what a failure
// leaves behind: the frame's error names what failed, the Renderer keeps its last good state,
// the editor keeps the document. Sites count their calls; an armed site fails its nth call from
// the moment it was armed, once. Armed by tests through arm_fault(), or for a whole process by
// the environment: LUMAGRAPH_FAULT=site:n[,site:n...], e.g. LUMAGRAPH_FAULT=device_allocation:12.
// Unarmed, a site costs one relaxed atomic load.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace lg {

enum class FaultSite {
  device_allocation,  // vkAllocateMemory (runtime/gpu/memory.cpp): VK_ERROR_OUT_OF_DEVICE_MEMORY
  shader_module,      // vkCreateShaderModule (runtime/gpu/pipeline.cpp): VK_ERROR_OUT_OF_HOST_MEMORY
  file_read,          // read_json_file (graph/json_reader.cpp): EIO while reading
  file_write,         // write_file_atomically (graph/json_writer.cpp): ENOSPC while writing
};

std::optional<FaultSite> fault_site_named(std::string_view name);

// The site's nth call from now fails (n >= 1); n = 0 disarms it.
void arm_fault(FaultSite site, uint64_t nth);
// Calls made at the site since it was last armed, counted only while armed (arm with a huge n
// to count calls without failing one).
uint64_t fault_site_calls(FaultSite site);
// At each site, once per call: true when this call is to fail (then the site is disarmed).
bool inject_fault(FaultSite site);

}  // namespace lg
