// The specular term of a lit frame against the path tracer's specular AOV, over a mask of metal
// pixels: on a metal there is no diffuse part, so lighting.ibl's colour less the direct light is
// its specular term alone, what the AOV holds. The error is the mean absolute difference per
// channel relative to the reference's mean over the mask; the reference's own noise (its mean
// standard error, likewise relative) is reported beside it, since it sits in every error.
#pragma once

#include <cstddef>
#include <vector>

#include "nodes/gi/path_tracer/path_tracer.h"
#include "runtime/scene/world.h"

namespace lg::test {

// Metal pixels (metalness above 0.5) whose perceptual roughness is within 0.005 of `roughness`
// (a material of the world: the floor, the ball), or every metal pixel when it is negative.
struct SurfaceMask {
  float roughness = -1.0f;
  bool contains(const float* material_texel) const;
};

struct SpecularError {
  size_t pixels = 0;
  double relative = 0;  // mean |lit - direct - reference| / mean reference
  double noise = 0;     // mean standard error of the reference / mean reference
};

// `lit`, `direct` and `material` are float RGBA frames the reference's size.
SpecularError specular_error(const ReferenceImage& reference, const std::vector<float>& lit,
                             const std::vector<float>& direct, const std::vector<float>& material, SurfaceMask mask);

// Where the error is, as a picture three frames wide: the frame's specular term (lit less
// direct) over the mask, the reference's specular AOV over it, and their signed difference (red:
// too bright, blue: too dark, full at `scale` times the reference's mean over the mask). The first
// two map the reference's mean to 0.5 by x / (1 + x); pixels outside the mask are black. RGBA,
// 3 width x height.
std::vector<float> specular_error_picture(const ReferenceImage& reference, const std::vector<float>& lit,
                                          const std::vector<float>& direct, const std::vector<float>& material,
                                          SurfaceMask mask, double scale);

// The path-traced reference of `world` seen by its camera at width x height.
ReferenceImage trace_specular_reference(const World& world, uint32_t width, uint32_t height, uint32_t paths,
                                        const PathEnvironment& environment);

}  // namespace lg::test
