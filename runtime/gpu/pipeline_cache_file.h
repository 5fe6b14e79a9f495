// The file a driver's pipeline cache is kept in between runs: our header (magic, format
// version, the device it was made on, payload size and checksum) and then the driver's own
// data from vkGetPipelineCacheData, which starts with VkPipelineCacheHeaderVersionOne. Decoding
// checks both headers before anything reaches the driver, so a truncated, corrupt or foreign
// file (another GPU, another driver version) is refused with the reason. Pure functions: no
// Vulkan calls, no files.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lg {

// What a driver's pipeline cache data is valid for.
struct DeviceIdentity {
  uint32_t vendor_id = 0, device_id = 0, driver_version = 0;
  std::array<uint8_t, VK_UUID_SIZE> cache_uuid{};
  bool operator==(const DeviceIdentity&) const = default;
};

DeviceIdentity device_identity(const VkPhysicalDeviceProperties& properties);

// The identity in cache files' headers (byte_stream.h), and in messages.
constexpr size_t device_identity_bytes = 3 * 4 + VK_UUID_SIZE;
class ByteWriter;
class ByteReader;
void put_device_identity(ByteWriter& out, const DeviceIdentity& device);
DeviceIdentity get_device_identity(ByteReader& in);  // device_identity_bytes of them
std::string describe_device(const DeviceIdentity& device);

// "pipeline-cache-<16 hex digits>.bin", the digits a hash of the identity: one file per device
// and driver, so two GPUs (or a driver update) never overwrite each other's cache.
std::string pipeline_cache_file_name(const DeviceIdentity& device);

// The file's bytes for `driver_data` made on `device`.
std::string encode_pipeline_cache(const DeviceIdentity& device, std::span<const std::byte> driver_data);

struct DecodedPipelineCache {
  std::vector<std::byte> driver_data;  // empty when refused
  std::string problem;                 // why it was refused ("truncated: ..."); empty when accepted
};

// The driver data of a file's bytes, when both headers match `device` and the checksum holds.
DecodedPipelineCache decode_pipeline_cache(std::string_view file, const DeviceIdentity& device);

}  // namespace lg
