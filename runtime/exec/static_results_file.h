// The file a plan's static results (the bytes of its cached resources: an environment cube, its
// SH, a BRDF table) are kept in between runs (static_results_store.h): our header (magic, format
// version, the device they were made on, the key they were made for, payload size and checksum),
// then each resource's name and bytes. Decoding checks all of it, so a truncated, corrupt or
// foreign file is refused with the reason. Pure functions: no Vulkan calls, no files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "graph/plan.h"
#include "runtime/gpu/pipeline_cache_file.h"

namespace lg {

// What the bytes of a plan's static results depend on beyond the plan itself.
struct StaticResultsIdentity {
  DeviceIdentity device;  // the driver that computed them
  uint64_t code = 0;      // the shaders' SPIR-V and the build that records them
  uint64_t inputs = 0;    // the contents of the files static nodes read (env.load's image)
};

// Whether a plan's resource is one of its static results: cached and placed in memory (what the
// key covers, the file holds and the executor reads back and loads).
inline bool is_static_result(const PlanResource& r) {
  return r.desc.lifetime == ResourceLifetime::cached && r.placement.block >= 0;
}

// A hash of everything that changes the static results' bytes: every static pass's name and
// cache key (the node's type, params and static inputs), every cached resource's name, kind,
// format, extent, layers, mips and size, and `identity`. 0 when the plan has no static pass.
uint64_t static_results_key(const Plan& plan, const StaticResultsIdentity& identity);

// "static-results-<16 hex digits of the key>.bin".
std::string static_results_file_name(uint64_t key);

struct StoredResult {
  std::string name;  // the plan resource's: "specular.specular"
  std::vector<std::byte> bytes;
};

std::string encode_static_results(const DeviceIdentity& device, uint64_t key, std::span<const StoredResult> results);

struct DecodedStaticResults {
  std::vector<StoredResult> results;  // empty when refused
  std::string problem;                // why it was refused ("truncated: ..."); empty when accepted
};

// The results in a file's bytes, when its header names `device` and `key` and the checksum holds.
DecodedStaticResults decode_static_results(std::string_view file, const DeviceIdentity& device, uint64_t key);

}  // namespace lg
