// A made-up device for the tests of the files keyed by one (the pipeline cache's, the static
// results'), which need no GPU.
#pragma once

#include "runtime/gpu/pipeline_cache_file.h"

namespace lg::test {

inline DeviceIdentity test_device() {
  DeviceIdentity d;
  d.vendor_id = 0x10005;
  d.device_id = 0x1234;
  d.driver_version = 0x00580006;
  for (size_t i = 0; i < d.cache_uuid.size(); ++i) d.cache_uuid[i] = uint8_t(17 * i + 3);
  return d;
}

}  // namespace lg::test
