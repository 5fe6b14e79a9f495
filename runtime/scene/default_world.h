// The embedded default world, needing no files: a room open toward the camera with a row of
// spheres of graded roughness, a row of graded metalness, a procedural bunny, a sun with
// shadows, the procedural sky, a sphere light and a tube light, seen through a pinhole camera
// framed for 16:9. Its summary is graph/scene_summary.h's default_scene_summary().
#pragma once

#include "runtime/scene/world.h"

namespace lg {

World default_world();

}  // namespace lg
