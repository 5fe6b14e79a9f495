// Synchronization as plain data, named after Vulkan's synchronization2 flags and layouts so the
// runtime maps them one to one, without graph/ including Vulkan.
#pragma once

#include <cstdint>
#include <string>

namespace lg {

enum Stage : uint32_t {
  stage_none = 0,
  stage_compute_shader = 1u << 0,
  stage_fragment_shader = 1u << 1,
  stage_color_attachment_output = 1u << 2,
  stage_early_fragment_tests = 1u << 3,
  stage_late_fragment_tests = 1u << 4,
};

enum Access : uint32_t {
  access_none = 0,
  access_shader_sampled_read = 1u << 0,
  access_shader_storage_read = 1u << 1,
  access_shader_storage_write = 1u << 2,
  access_color_attachment_read = 1u << 3,
  access_color_attachment_write = 1u << 4,
  access_depth_stencil_attachment_read = 1u << 5,
  access_depth_stencil_attachment_write = 1u << 6,
  access_uniform_read = 1u << 7,
};
inline constexpr uint32_t access_write_mask =
    access_shader_storage_write | access_color_attachment_write | access_depth_stencil_attachment_write;

enum class Layout : uint8_t { undefined, general, read_only, attachment, none /* buffers */ };

enum class BarrierReason : uint8_t {
  first_use,          // an image's initial layout transition
  alias,              // takes over bytes another resource used earlier in the frame
  history,            // across frames: previous-frame copy and its current partner
  read_after_write,
  write_after_read,
  write_after_write,
  layout_transition,  // between reads that need different layouts
};

struct Barrier {
  int before = -1;    // position in the schedule of the pass that waits
  int resource = -1;
  uint32_t src_stages = 0, src_access = 0, dst_stages = 0, dst_access = 0;
  Layout old_layout = Layout::none, new_layout = Layout::none;
  BarrierReason reason = BarrierReason::first_use;
  // Hands a cached result from its static pass to its first reader. On a frame whose cached
  // passes are skipped (their keys unchanged) it is skipped too: the image already sits in its
  // readers' layout from the frames before.
  bool skip_when_cached = false;
};

std::string stage_names(uint32_t stages);
std::string access_names(uint32_t access);
std::string_view layout_name(Layout l);
std::string_view barrier_reason_name(BarrierReason r);

}  // namespace lg
