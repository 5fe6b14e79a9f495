// The camera-view ray-traced reference on the full scene geometry: for the camera and frame
// size of a GPU render, one primary ray per pixel centre (camera_pixels.h, the rasterizer's
// projection), then AoSettings::rays stratified cosine rays about the surface's interpolated
// shading normal (what the G-buffer stores), traced with Embree (nodes/raytrace) on
// all cores, for k_A, the bent normal and its cone.
#pragma once

#include <cstdint>

#include "nodes/raytrace/ray_scene.h"
#include "nodes/occlusion/reference/ao_image.h"
#include "nodes/occlusion/reference/ao_sampling.h"
#include "runtime/scene/scene_view.h"

namespace lg {

struct SceneReferenceOptions {
  uint32_t width = 0, height = 0;  // the G-buffer's size
  // As scene.gbuffer's cull_backfaces: true skips back faces for the primary ray (the pixel
  // shows what lies behind them); false shows them with the normal turned toward the camera,
  // as the G-buffer does for two-sided drawing.
  bool cull_backfaces = true;
};

// `scene` must be RayScene(view) (its primitives are the view's draws in order). Pixels whose
// primary ray hits nothing stay NaN.
AoImage trace_scene_reference(const SceneView& view, const RayScene& scene, const SceneReferenceOptions& options,
                              const AoSettings& settings);

}  // namespace lg
