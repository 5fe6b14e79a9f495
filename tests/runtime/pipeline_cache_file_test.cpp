// The pipeline cache file (runtime/gpu/pipeline_cache_file.h) without a device: what it encodes
// decodes to the same driver data, and every way a file goes wrong — cut short at any length,
// any byte flipped, made on another device or driver — is refused with its reason, never handed
// on and never a crash.
#include "runtime/gpu/pipeline_cache_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <string>

#include "runtime/gpu/pipeline_cache_store.h"
#include "tests/runtime/test_device_identity.h"

namespace lg {
namespace {

using test::test_device;

// Driver data as a driver writes it: VkPipelineCacheHeaderVersionOne for `device`, then payload.
std::vector<std::byte> driver_data(const DeviceIdentity& device, size_t payload) {
  std::vector<std::byte> data(32 + payload);
  const uint32_t header[4] = {32, VK_PIPELINE_CACHE_HEADER_VERSION_ONE, device.vendor_id, device.device_id};
  std::memcpy(data.data(), header, sizeof header);
  std::memcpy(data.data() + 16, device.cache_uuid.data(), VK_UUID_SIZE);
  std::mt19937 random(7);
  for (size_t i = 32; i < data.size(); ++i) data[i] = std::byte(random());
  return data;
}

TEST(PipelineCacheFile, RoundTripsTheDriverData) {
  const DeviceIdentity device = test_device();
  for (size_t payload : {size_t{0}, size_t{1}, size_t{4093}}) {
    const std::vector<std::byte> data = driver_data(device, payload);
    const DecodedPipelineCache decoded = decode_pipeline_cache(encode_pipeline_cache(device, data), device);
    EXPECT_EQ(decoded.problem, "");
    EXPECT_EQ(decoded.driver_data, data);
  }
}

TEST(PipelineCacheFile, ATruncatedFileIsRefusedAtEveryLength) {
  const DeviceIdentity device = test_device();
  const std::string file = encode_pipeline_cache(device, driver_data(device, 100));
  for (size_t length = 0; length < file.size(); ++length) {
    const DecodedPipelineCache decoded = decode_pipeline_cache(file.substr(0, length), device);
    EXPECT_NE(decoded.problem, "") << length;
    EXPECT_TRUE(decoded.driver_data.empty()) << length;
    EXPECT_NE(decoded.problem.find("truncated"), std::string::npos) << decoded.problem;
  }
  EXPECT_NE(decode_pipeline_cache(file + "x", device).problem, "") << "a byte too many";
}

TEST(PipelineCacheFile, EveryFlippedByteIsRefused) {
  const DeviceIdentity device = test_device();
  const std::string file = encode_pipeline_cache(device, driver_data(device, 64));
  for (size_t i = 0; i < file.size(); ++i) {
    std::string bad = file;
    bad[i] = char(bad[i] ^ 0x20);
    const DecodedPipelineCache decoded = decode_pipeline_cache(bad, device);
    EXPECT_NE(decoded.problem, "") << "byte " << i;
    EXPECT_TRUE(decoded.driver_data.empty()) << "byte " << i;
  }
}

TEST(PipelineCacheFile, AFileOfAnotherDeviceOrDriverIsRefused) {
  const DeviceIdentity device = test_device();
  DeviceIdentity other_uuid = device, other_driver = device, other_gpu = device;
  other_uuid.cache_uuid[5] ^= 1;
  other_driver.driver_version += 1;
  other_gpu.device_id += 1;
  for (const DeviceIdentity& other : {other_uuid, other_driver, other_gpu}) {
    const DecodedPipelineCache decoded =
        decode_pipeline_cache(encode_pipeline_cache(other, driver_data(other, 16)), device);
    EXPECT_NE(decoded.problem.find("another device or driver"), std::string::npos) << decoded.problem;
    EXPECT_NE(pipeline_cache_file_name(other), pipeline_cache_file_name(device));
  }
  EXPECT_EQ(pipeline_cache_file_name(device), pipeline_cache_file_name(test_device()));
}

// Our header right, the driver's own header wrong: its data never reaches the driver.
TEST(PipelineCacheFile, ADriverHeaderThatDoesNotMatchIsRefused) {
  const DeviceIdentity device = test_device();
  DeviceIdentity foreign = device;
  foreign.cache_uuid[0] ^= 0xff;
  std::vector<std::vector<std::byte>> bad = {driver_data(foreign, 8), driver_data(device, 8), driver_data(device, 8),
                                             std::vector<std::byte>(10)};
  const uint32_t version = 7, size = 4000;
  std::memcpy(bad[1].data() + 4, &version, 4);
  std::memcpy(bad[2].data(), &size, 4);
  for (const auto& data : bad) {
    const DecodedPipelineCache decoded = decode_pipeline_cache(encode_pipeline_cache(device, data), device);
    EXPECT_NE(decoded.problem.find("driver"), std::string::npos) << decoded.problem;
    EXPECT_TRUE(decoded.driver_data.empty());
  }
}

TEST(PipelineCacheFile, AnotherFileIsNotTakenForOne) {
  const DecodedPipelineCache decoded = decode_pipeline_cache(std::string(200, '{'), test_device());
  EXPECT_NE(decoded.problem.find("wrong magic"), std::string::npos) << decoded.problem;
}

// Sets an environment variable for one scope, restoring what was there.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value, 1) : ::unsetenv(name);
  }
  ~ScopedVariable() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(PipelineCacheFolder, IsUnderXdgCacheHomeElseHome) {
  ScopedVariable home("HOME", "/home/someone");
  {
    ScopedVariable xdg("XDG_CACHE_HOME", "/var/cache/me");
    EXPECT_EQ(default_pipeline_cache_folder(), "/var/cache/me/lumagraph");
  }
  ScopedVariable no_xdg("XDG_CACHE_HOME", nullptr);
  EXPECT_EQ(default_pipeline_cache_folder(), "/home/someone/.cache/lumagraph");
  ScopedVariable no_home("HOME", nullptr);
  EXPECT_EQ(default_pipeline_cache_folder(), "");
}

TEST(PipelineCacheFolder, TheEnvironmentTurnsTheFileOff) {
  for (const char* off : {"off", "0", "false", "no"}) {
    ScopedVariable variable("LUMAGRAPH_PIPELINE_CACHE", off);
    EXPECT_TRUE(pipeline_cache_disabled_by_environment()) << off;
  }
  for (const char* on : {"on", "1", ""}) {
    ScopedVariable variable("LUMAGRAPH_PIPELINE_CACHE", on);
    EXPECT_FALSE(pipeline_cache_disabled_by_environment()) << on;
  }
  ScopedVariable unset("LUMAGRAPH_PIPELINE_CACHE", nullptr);
  EXPECT_FALSE(pipeline_cache_disabled_by_environment());
}

}  // namespace
}  // namespace lg
