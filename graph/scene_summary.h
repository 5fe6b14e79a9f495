// What a scene contains, as far as the compiler cares: which kinds of lights, probes, materials
// and camera it has. Specialization bypasses nodes and passes whose needs are absent. The
// runtime derives a summary from its world; `lumagraph compile --scene FILE` reads one from JSON.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "graph/diagnostics.h"
#include "graph/json_value.h"

namespace lg {

enum class SceneFeature : uint8_t {
  directional_lights,
  point_lights,
  spot_lights,
  sphere_lights,
  tube_lights,
  rectangle_lights,
  area_lights,  // any of sphere, tube, rectangle
  lights,       // any light at all: directional, point, spot or area
  shadow_casting_lights,
  local_shadow_casting_lights,  // a point, spot, sphere, tube or rectangle light that casts shadows
  environment_light,
  irradiance_volumes,
  reflection_probes,
  glossy_materials,
  thin_lens_camera,
  baked_occlusion,     // a drawn mesh carries occlusion baked offline (a scene file's "occlusion")
  blend_materials,     // something is drawn with a glTF alphaMode BLEND (transparent) material
  emissive_materials,  // something is drawn with a material that emits light (emissive factor above 0)
  planar_reflectors,   // a drawn flat mesh marked to reflect as a mirror plane (gi.planar_reflection)
  count
};

std::optional<SceneFeature> parse_scene_feature(std::string_view name);
// Why a node that needs `f` is skipped when the scene lacks it, e.g. "the scene has no area lights".
std::string scene_lacks_reason(SceneFeature f);

struct SceneSummary {
  std::string name = "default";
  int directional_lights = 1;
  int point_lights = 0;
  int spot_lights = 0;
  int sphere_lights = 1;
  int tube_lights = 1;
  int rectangle_lights = 0;
  bool shadows = true;
  bool local_shadows = false;  // whether the point, spot and area lights cast shadows
  bool environment = true;
  int irradiance_volumes = 0;
  int reflection_probes = 0;
  int planar_reflectors = 0;  // distinct planes
  bool glossy_materials = true;
  bool baked_occlusion = false;
  bool blend_materials = false;
  bool emissive_materials = false;
  double aperture = 0;  // lens aperture diameter in metres; 0 is a pinhole camera
  double focus_distance = 5;

  bool has(SceneFeature f) const;
  friend bool operator==(const SceneSummary&, const SceneSummary&) = default;
};

// The embedded default scene (a room lit by a sky with a sun, a sphere light and a tube light,
// seen through a pinhole camera).
SceneSummary default_scene_summary();

std::optional<SceneSummary> scene_summary_from_json(const JsonValue& root, Diagnostics& diagnostics);
std::optional<SceneSummary> load_scene_summary(const std::string& path, Diagnostics& diagnostics);

}  // namespace lg
