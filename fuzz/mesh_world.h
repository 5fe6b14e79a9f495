// What the mesh harnesses (OBJ, glTF) do with a file once written: load it as a world the way
// `lumagraph render --scene FILE` does (import, viewing defaults), then build its SceneView.
// A bad file must be a SceneError, never a crash.
#pragma once

#include <string>

namespace lg::fuzz {

void load_mesh_world(const std::string& path);

}  // namespace lg::fuzz
