// What post.taa's tests and its benchmark share: the graphs (the default world's G-buffer lit by
// lighting.deferred, with post.taa or without it), the supersampled reference (the same frame
// rendered at many jitter positions of the same Halton (2, 3) sequence and averaged), and the
// measures: error against the reference and the difference between consecutive frames, both on
// radiance compressed as x / (1 + x) per channel, so a highlight counts like a display shows it
// rather than by its raw radiance.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "api/renderer.h"

namespace lg::test {

// "gbuf" -> "light" (lighting.deferred, its sun's shadow map at 512 texels, which keeps 64
// reference frames cheap), and with `taa` also -> "taa" (post.taa with `taa_params`, its
// accumulated output linked back to its history). Results: light.color, and taa.color.
Graph taa_test_graph(bool taa, const std::string& taa_params = "{}");

// A renderer with validation on (unless `validation` is false, for timings) and no aliasing, so
// every resource can be read after the frame.
RendererOptions taa_renderer_options(bool validation = true);

// The mean of light.color over `samples` frames of the graph without post.taa, frame i jittered
// by halton_jitter_pixels(i): the box-filtered supersampled image the accumulation approaches.
std::vector<float> supersampled_reference(Renderer& renderer, const World& world, FrameSize size, uint32_t samples);

// RMS over pixels and rgb channels of the difference of x / (1 + x) (rgba images, alpha ignored).
double compressed_rms_error(const std::vector<float>& image, const std::vector<float>& reference);

// Mean over pixels and rgb of |a - b| after x / (1 + x): flicker between two frames.
double compressed_mean_abs_difference(const std::vector<float>& a, const std::vector<float>& b);

// The crawl of aliasing on a moving camera: mean over pixels and rgb of how much a frame's error
// against its reference changed since the previous frame's, |(F - R) - (F' - R')| after
// x / (1 + x). The true image's motion is in both references, so only the change of the error
// counts.
double aliasing_crawl(const std::vector<float>& frame, const std::vector<float>& reference,
                      const std::vector<float>& previous, const std::vector<float>& previous_reference);

// Moves the world's active camera by `offset` metres (world space).
void move_camera(World& world, glm::vec3 offset);

}  // namespace lg::test
