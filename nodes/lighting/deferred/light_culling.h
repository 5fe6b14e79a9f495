// Which lights the deferred node shades in a frame: a point or spot light with a range reaches
// nothing past it (the range window is exactly 0 there, shaders/direct.comp), and a spot
// nothing outside its outer cone (the cone's falloff is exactly 0 there), so one whose range
// sphere, or cone cut by its range, misses the camera's frustum cannot light a visible surface
// and is left out of the light lists and of the shadow budget's choice. Point lights without a
// range, directional lights, and sphere, tube and rectangle lights (this node gives them no
// cut-off distance: their light only falls off) reach everything and are always kept.
#pragma once

#include "runtime/scene/frustum.h"
#include "runtime/scene/scene_view.h"

namespace lg {

bool reaches(const Frustum& frustum, const PointLightData& light);
bool reaches(const Frustum& frustum, const SpotLightData& light);

// The scene's camera and its lights, the point and spot lights reduced to those that reach the
// camera's frustum (in the scene's order); no draws or assets. With `cull` false, every light.
SceneView lights_in_view(const SceneView& scene, bool cull = true);

}  // namespace lg
