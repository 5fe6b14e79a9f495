#include "runtime/gpu/pipeline_cache_file.h"

#include <cstring>

#include "graph/fnv1a.h"
#include "runtime/gpu/byte_stream.h"

namespace lg {
namespace {

constexpr char magic[8] = {'L', 'G', 'P', 'C', 'A', 'C', 'H', 'E'};
constexpr uint32_t format_version = 1;
// magic, version, vendor, device, driver version, UUID, payload size, payload checksum.
constexpr size_t header_bytes = sizeof magic + 4 + device_identity_bytes + 8 + 8;
// VkPipelineCacheHeaderVersionOne: headerSize, headerVersion, vendorID, deviceID, UUID.
constexpr size_t driver_header_bytes = 4 * 4 + VK_UUID_SIZE;

// What is wrong with the driver's own header, which the spec lets the driver trust.
std::string driver_header_problem(std::string_view data, const DeviceIdentity& device) {
  if (data.size() < driver_header_bytes)
    return "the driver data (" + std::to_string(data.size()) + " bytes) is shorter than its " +
           std::to_string(driver_header_bytes) + "-byte header";
  ByteReader in(data);
  const auto size = in.get<uint32_t>();
  const auto version = in.get<uint32_t>();
  if (size < driver_header_bytes || size > data.size())
    return "the driver header says it is " + std::to_string(size) + " bytes long, of " + std::to_string(data.size());
  if (version != VK_PIPELINE_CACHE_HEADER_VERSION_ONE)
    return "the driver header has version " + std::to_string(version) + ", not VK_PIPELINE_CACHE_HEADER_VERSION_ONE";
  const auto vendor = in.get<uint32_t>();
  const auto device_id = in.get<uint32_t>();
  std::array<uint8_t, VK_UUID_SIZE> uuid;
  std::memcpy(uuid.data(), in.get_bytes(VK_UUID_SIZE).data(), VK_UUID_SIZE);
  if (vendor != device.vendor_id || device_id != device.device_id || uuid != device.cache_uuid)
    return "the driver header names another device or pipeline cache UUID";
  return {};
}

}  // namespace

std::string describe_device(const DeviceIdentity& d) {
  return "vendor 0x" + hex_digits(d.vendor_id, 4) + ", device 0x" + hex_digits(d.device_id, 4) + ", driver version 0x" +
         hex_digits(d.driver_version, 8);
}

void put_device_identity(ByteWriter& out, const DeviceIdentity& d) {
  out.put(d.vendor_id);
  out.put(d.device_id);
  out.put(d.driver_version);
  out.put_bytes(d.cache_uuid.data(), VK_UUID_SIZE);
}

DeviceIdentity get_device_identity(ByteReader& in) {
  DeviceIdentity d;
  d.vendor_id = in.get<uint32_t>();
  d.device_id = in.get<uint32_t>();
  d.driver_version = in.get<uint32_t>();
  std::memcpy(d.cache_uuid.data(), in.get_bytes(VK_UUID_SIZE).data(), VK_UUID_SIZE);
  return d;
}

DeviceIdentity device_identity(const VkPhysicalDeviceProperties& properties) {
  DeviceIdentity d;
  d.vendor_id = properties.vendorID;
  d.device_id = properties.deviceID;
  d.driver_version = properties.driverVersion;
  std::memcpy(d.cache_uuid.data(), properties.pipelineCacheUUID, VK_UUID_SIZE);
  return d;
}

std::string pipeline_cache_file_name(const DeviceIdentity& device) {
  ByteWriter identity;
  put_device_identity(identity, device);
  return "pipeline-cache-" + hex_digits(fnv1a(as_byte_span(identity.take())), 16) + ".bin";
}

std::string encode_pipeline_cache(const DeviceIdentity& device, std::span<const std::byte> driver_data) {
  ByteWriter out;
  out.put_bytes(magic, sizeof magic);
  out.put(format_version);
  put_device_identity(out, device);
  out.put(static_cast<uint64_t>(driver_data.size()));
  out.put(fnv1a(driver_data));
  out.put_bytes(driver_data.data(), driver_data.size());
  return out.take();
}

DecodedPipelineCache decode_pipeline_cache(std::string_view file, const DeviceIdentity& device) {
  auto refuse = [](std::string why) { return DecodedPipelineCache{{}, std::move(why)}; };
  if (file.size() < header_bytes)
    return refuse("truncated: " + std::to_string(file.size()) + " bytes, shorter than the " +
                  std::to_string(header_bytes) + "-byte header");
  ByteReader in(file);
  if (in.get_bytes(sizeof magic) != std::string_view(magic, sizeof magic))
    return refuse("not a Lumagraph pipeline cache (wrong magic)");
  if (const auto version = in.get<uint32_t>(); version != format_version)
    return refuse("format version " + std::to_string(version) + ", this build reads " + std::to_string(format_version));
  if (const DeviceIdentity made_on = get_device_identity(in); !(made_on == device))
    return refuse("made on another device or driver (" + describe_device(made_on) + "; this is " +
                  describe_device(device) +
                  (made_on.cache_uuid != device.cache_uuid ? ", another pipeline cache UUID)" : ")"));
  const auto payload_size = in.get<uint64_t>();
  const auto checksum = in.get<uint64_t>();
  if (payload_size != file.size() - header_bytes)
    return refuse("truncated or padded: the header promises " + std::to_string(payload_size) +
                  " bytes of driver data, the file holds " + std::to_string(file.size() - header_bytes));
  const std::string_view payload = in.get_bytes(payload_size);
  if (fnv1a(as_byte_span(payload)) != checksum) return refuse("corrupt: the driver data's checksum does not match");
  if (std::string problem = driver_header_problem(payload, device); !problem.empty()) return refuse(problem);
  const auto bytes = as_byte_span(payload);
  return {{bytes.begin(), bytes.end()}, {}};
}

}  // namespace lg
