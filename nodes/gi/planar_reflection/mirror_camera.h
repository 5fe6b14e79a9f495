// The frame's camera mirrored in a reflector's plane (docs/planar-reflections.md). A point of the
// plane is its own mirror image, so it projects to the same pixel in both cameras, and what the
// mirrored view shows there beyond the plane is what the mirror reflects at that pixel. The
// mirrored view is a mirror image of a right-handed camera's: front faces wind clockwise in it.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "nodes/common/camera_constants.h"

namespace lg {

// Reflection in the plane (xyz a unit normal n, w: n . p + w = 0): p - 2 (n . p + w) n.
glm::mat4 mirror_matrix(const glm::vec4& plane);

// The frame's camera (its jitter included) mirrored in `plane`, for a target of width x height.
// No motion: previous_view_projection is this frame's.
CameraConstants mirrored_camera(const CameraView& camera, const glm::vec4& plane, uint32_t width, uint32_t height);

}  // namespace lg
