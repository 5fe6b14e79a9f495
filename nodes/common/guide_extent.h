// How an image a node reads relates to the G-buffer that guides it (post.bilateral,
// post.upsample): the schema sizes outputs from one input but cannot relate two inputs, so the
// kernel checks them when it records, naming the node and both sizes.
#pragma once

#include <string_view>

#include "graph/plan.h"
#include "runtime/gpu/image.h"

namespace lg {

// The whole number k for which `image` is the G-buffer `guide` at 1/k, as the compiler sizes a
// resource of scale 1/k (floor(guide / k) in each direction; 1: the same size). Throws
// std::invalid_argument naming the node, the input and both sizes when there is none.
int guide_divisor(const PlanNode& node, std::string_view input, const ImageDesc& image, const ImageDesc& guide);

// Throws as guide_divisor does unless `image` has the G-buffer's size.
void require_guide_size(const PlanNode& node, std::string_view input, const ImageDesc& image, const ImageDesc& guide);

}  // namespace lg
