#include "nodes/common/guide_extent.h"

#include <stdexcept>
#include <string>

namespace lg {
namespace {

std::string extent(const ImageDesc& d) {
  return std::to_string(d.width) + "x" + std::to_string(d.height);
}

[[noreturn]] void fail(const PlanNode& node, std::string_view input, const ImageDesc& image, const ImageDesc& guide,
                       std::string_view expected) {
  throw std::invalid_argument(node.type + " '" + node.id + "': input '" + std::string(input) + "' is " + extent(image) +
                              " and the G-buffer that guides it " + extent(guide) + "; expected " +
                              std::string(expected));
}

}  // namespace

int guide_divisor(const PlanNode& node, std::string_view input, const ImageDesc& image, const ImageDesc& guide) {
  const uint32_t k = image.width > 0 ? guide.width / image.width : 0;
  if (k == 0 || guide.width / k != image.width || guide.height / k != image.height)
    fail(node, input, image, guide,
         "it at the G-buffer's size over a whole number (1, 2, 4: a resolution_scale of 1, 0.5, 0.25)");
  return int(k);
}

void require_guide_size(const PlanNode& node, std::string_view input, const ImageDesc& image, const ImageDesc& guide) {
  if (image.width != guide.width || image.height != guide.height) fail(node, input, image, guide, "the same size");
}

}  // namespace lg
