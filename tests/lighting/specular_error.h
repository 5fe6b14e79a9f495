// The specular term of a lit frame against the path tracer's specular AOV, over a mask of metal
// pixels: on a metal there is no diffuse part, so lighting.ibl's colour less the direct light is
// its specular term alone, what the AOV holds. The error is the mean absolute difference per
// channel relative to the reference's mean over the mask; the reference's own noise (its mean
// standard error, likewise relative) is reported beside it, since it sits in every error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "nodes/gi/path_tracer/path_tracer.h"
#include "runtime/scene/world.h"

namespace lg::test {

// Metal pixels (metalness above 0.5) whose perceptual roughness is within 0.005 of `roughness`
// (a material of the world: the floor, the ball), or every metal pixel when it is negative; where
// `pixels` is given (one byte a pixel, e.g. captured_reflection_mask()), only those where it is 1.
struct SurfaceMask {
  float roughness = -1.0f;
  const std::vector<uint8_t>* pixels = nullptr;
  bool contains(size_t pixel, const float* material_texel) const;
};

struct SpecularError {
  size_t pixels = 0;
  double relative = 0;  // mean |lit - direct - reference| / mean reference
  double noise = 0;     // mean standard error of the reference / mean reference
};

// The error with the reference's noise taken out, from two references traced with independent
// seeds, a and b: sqrt(max(0, mean((x - a)(x - b)))) over the mask's pixels and channels, over the
// mean of (a + b) / 2. For independent unbiased references E[(x - a)(x - b)] = (x - truth)^2, so
// the noise that every plain error carries (and that shrinks the ratio of two errors toward 1)
// cancels in expectation; it equals mean((x - m)^2) - mean((a - b)^2) / 4 with m = (a + b) / 2,
// the squared error against m less m's noise variance estimated from the two traces, and needs
// no per-pixel standard error (the tracer's own estimate of it is noisy where fireflies are).
struct DebiasedError {
  size_t pixels = 0;
  double rms = 0;        // the debiased RMS error / mean reference
  double plain_rms = 0;  // sqrt(mean((x - m)^2)) / mean reference, noise included
  double noise_rms = 0;  // sqrt(mean((a - b)^2) / 4) / mean reference: m's own noise
};

// `lit`, `direct` and `material` are float RGBA frames the reference's size.
SpecularError specular_error(const ReferenceImage& reference, const std::vector<float>& lit,
                             const std::vector<float>& direct, const std::vector<float>& material, SurfaceMask mask);

DebiasedError debiased_specular_error(const ReferenceImage& a, const ReferenceImage& b, const std::vector<float>& lit,
                                    const std::vector<float>& direct, const std::vector<float>& material,
                                    SurfaceMask mask);

// Two references of the same view and paths with independent seeds as one with twice the paths:
// the mean of their means, standard errors combined as sqrt(ea^2 + eb^2) / 2.
ReferenceImage average_references(const ReferenceImage& a, const ReferenceImage& b);

// Where the error is, as a picture three frames wide: the frame's specular term (lit less
// direct) over the mask, the reference's specular AOV over it, and their signed difference (red:
// too bright, blue: too dark, full at `scale` times the reference's mean over the mask). The first
// two map the reference's mean to 0.5 by x / (1 + x); pixels outside the mask are black. RGBA,
// 3 width x height.
std::vector<float> specular_error_picture(const ReferenceImage& reference, const std::vector<float>& lit,
                                          const std::vector<float>& direct, const std::vector<float>& material,
                                          SurfaceMask mask, double scale);

// The path-traced reference of `world` seen by its camera at width x height, its random numbers
// drawn from `seed` (two seeds: two independent references).
ReferenceImage trace_specular_reference(const World& world, uint32_t width, uint32_t height, uint32_t paths,
                                        const PathEnvironment& environment, uint64_t seed = 1);

}  // namespace lg::test
