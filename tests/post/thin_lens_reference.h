// The thin-lens ground truth that post.dof is measured against: the mean of pinhole renders from
// points spread over the camera's aperture disc (Camera::aperture is its diameter, in the
// camera's x-y plane), each view sheared so that the focus plane (Camera::focus_distance away)
// stays where the centre view sees it. The shear is a constant offset of clip x and y against w,
// which is what the camera's sub-pixel jitter already is (runtime/scene/camera_jitter.h), so each
// view is the world's camera moved on the disc and rendered with FrameTiming::jitter. Each view
// is also moved within its pixel (Halton (2, 3), as post.taa's reference is), so that the
// reference is the thin-lens image box-filtered over each pixel, in focus as out of it.
//
// The mapping to post.dof's lens (nodes/post/dof/dof_kernel.cpp): a camera moved by u on the
// disc sees a point at depth z shifted by u (1 / F - 1 / z) f pixels, f = (h / 2) / tan(fov / 2)
// (the focus plane's image distance in pixels); over the disc of diameter A the shifts fill a
// circle of diameter A f |1 / F - 1 / z|, which is post.dof's circle of confusion: the same
// camera, the same lens.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string_view>
#include <vector>

#include "api/renderer.h"

namespace lg::test {

// `count` points of Vogel's spiral over the disc of `diameter` (metres): evenly spread for any
// count, and the mean of |p|^2 is exactly (diameter / 2)^2 / 2, the uniform disc's.
std::vector<glm::vec2> aperture_samples(float diameter, uint32_t count);

// The jitter (pixels of `frame`) that keeps the focus plane still when `camera` moves by
// `offset` metres along its own x (right) and y (up).
glm::vec2 focus_plane_jitter(glm::vec2 offset, const Camera& camera, FrameSize frame);

// Radius in pixels of `camera`'s circle of confusion at view depth `depth` (metres along the view
// axis; infinity for the sky).
double coc_radius_pixels(const Camera& camera, FrameSize frame, double depth);

// The mean of result image `image` (e.g. "ibl.color") over `samples` frames of the renderer's
// graph, the world's active camera moved to each aperture sample and jittered to keep the focus
// plane still, plus halton_jitter_pixels(i) for view i. The camera (which must have no parent) is put back afterwards.
std::vector<float> thin_lens_reference(Renderer& renderer, World& world, FrameSize frame, uint32_t samples,
                                       std::string_view image);

}  // namespace lg::test
