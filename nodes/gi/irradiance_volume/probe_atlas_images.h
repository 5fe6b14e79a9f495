// A probe atlas (probe_atlas.h) on the device: its volumes in a uniform buffer and its three
// images, uploaded through a staging buffer by commands recorded ahead of the reads in the same
// command buffer. What gi.irradiance_volume's lookup binds; whoever changes probes (the in-graph
// bake, dynamic updates) packs them with pack_probe_atlas() and calls upload().
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <vector>

#include "nodes/gi/irradiance_volume/probe_atlas.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"

namespace lg {

class ProbeAtlasImages {
 public:
  ProbeAtlasImages(Context& gpu, std::string name);

  // Records the copy of `atlas` (images made again when their sizes change) and a barrier that
  // makes it visible to compute shaders' sampled reads. The staging memory stays until the next
  // upload, so the frame that records it may still be running.
  void upload(VkCommandBuffer cmd, const ProbeAtlas& atlas);

  // Records a copy of the volumes' block (what volumes() holds, kMaxProbeVolumes of them) into
  // `target` (gi.irradiance_volume's `probes` output, which compute passes write and read), with
  // the barriers from and to compute shaders around it.
  void copy_volumes(VkCommandBuffer cmd, VkBuffer target) const;

  VkBuffer volumes() const { return volumes_.handle(); }
  Image& records() { return *records_; }
  Image& irradiance() { return *irradiance_; }
  Image& distance() { return *distance_; }

 private:
  Context& gpu_;
  std::string name_;
  HostBuffer volumes_, staging_;
  std::vector<GpuProbeVolume> block_ = std::vector<GpuProbeVolume>(kMaxProbeVolumes);  // as volumes_ holds it
  std::optional<Image> records_, irradiance_, distance_;
};

}  // namespace lg
