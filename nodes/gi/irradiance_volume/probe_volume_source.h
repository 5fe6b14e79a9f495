// What gi.irradiance_volume lends the nodes that read its `probes` output (the raster captures of
// gi.reflection_capture and gi.planar_reflection): its probe atlas on the device and how its own
// lookup reads it, so a reader shades with the frame's irradiance (shaders/probe_volume.glsl).
// The plan's resource behind the output holds only the volumes' block, which the kernel copies
// there every frame; the atlas images change size with the world, so the reader asks the
// producing kernel for them (PassContext::producer, then dynamic_cast to this interface). The
// link orders the passes: the producer has baked and uploaded this frame's probes first.
#pragma once

#include <cstdint>

#include "nodes/gi/irradiance_volume/probe_atlas_images.h"

namespace lg {

struct ProbeVolumeBinding {
  ProbeAtlasImages* atlas = nullptr;  // null before the first bake
  uint32_t volume_count = 0;
  uint32_t representation = 3;                 // ProbeRepresentation, probe_volume.glsl's LG_PROBE_*
  bool visibility = true;                      // the Chebyshev test on the distance moments
  float normal_bias = 0.0f, view_bias = 0.0f;  // in cells
  uint64_t version = 0;  // of the last upload (probe_snapshot.h's): changes whenever the probes do
};

class ProbeVolumeSource {
 public:
  virtual ~ProbeVolumeSource() = default;
  virtual ProbeVolumeBinding probe_volume() = 0;
};

}  // namespace lg
