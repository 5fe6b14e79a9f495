#include "graph/scene_summary.h"

#include <cmath>
#include <functional>
#include <vector>

#include "graph/json_reader.h"

namespace lg {
namespace {

constexpr std::array<std::string_view, static_cast<size_t>(SceneFeature::count)> feature_names = {
    "directional_lights", "point_lights",          "spot_lights",
    "sphere_lights",      "tube_lights",           "rectangle_lights",
    "area_lights",        "lights",                "shadow_casting_lights", "local_shadow_casting_lights",
    "environment_light",  "irradiance_volumes",    "reflection_probes",
    "glossy_materials",   "thin_lens_camera",      "baked_occlusion",
    "blend_materials",    "emissive_materials",    "planar_reflectors"};

// One field of the summary file: where it lives and how it is read.
struct Field {
  std::string_view section, key;
  std::function<bool(const JsonValue&, SceneSummary&, std::string&)> read;
};

auto count_field(int SceneSummary::*member) {
  return [member](const JsonValue& v, SceneSummary& s, std::string& expected) {
    if (!v.is_integer() || v.as_number() < 0 || v.as_number() > 1e6) {
      expected = "a whole number from 0 to 1000000";
      return false;
    }
    s.*member = static_cast<int>(v.as_number());
    return true;
  };
}

auto bool_field(bool SceneSummary::*member) {
  return [member](const JsonValue& v, SceneSummary& s, std::string& expected) {
    if (!v.is_bool()) {
      expected = "true or false";
      return false;
    }
    s.*member = v.as_bool();
    return true;
  };
}

auto length_field(double SceneSummary::*member) {
  return [member](const JsonValue& v, SceneSummary& s, std::string& expected) {
    if (!v.is_number() || v.as_number() < 0 || v.as_number() > 1e6) {
      expected = "a length in metres from 0 to 1000000";
      return false;
    }
    s.*member = v.as_number();
    return true;
  };
}

const std::vector<Field>& fields() {
  static const std::vector<Field> table = {
      {"lights", "directional", count_field(&SceneSummary::directional_lights)},
      {"lights", "point", count_field(&SceneSummary::point_lights)},
      {"lights", "spot", count_field(&SceneSummary::spot_lights)},
      {"lights", "sphere", count_field(&SceneSummary::sphere_lights)},
      {"lights", "tube", count_field(&SceneSummary::tube_lights)},
      {"lights", "rectangle", count_field(&SceneSummary::rectangle_lights)},
      {"lights", "shadows", bool_field(&SceneSummary::shadows)},
      {"lights", "local_shadows", bool_field(&SceneSummary::local_shadows)},
      {"environment", "present", bool_field(&SceneSummary::environment)},
      {"probes", "irradiance_volumes", count_field(&SceneSummary::irradiance_volumes)},
      {"probes", "reflection_probes", count_field(&SceneSummary::reflection_probes)},
      {"probes", "planar_reflectors", count_field(&SceneSummary::planar_reflectors)},
      {"materials", "glossy", bool_field(&SceneSummary::glossy_materials)},
      {"materials", "blend", bool_field(&SceneSummary::blend_materials)},
      {"materials", "emissive", bool_field(&SceneSummary::emissive_materials)},
      {"occlusion", "baked", bool_field(&SceneSummary::baked_occlusion)},
      {"camera", "aperture", length_field(&SceneSummary::aperture)},
      {"camera", "focus_distance", length_field(&SceneSummary::focus_distance)},
  };
  return table;
}

}  // namespace

std::optional<SceneFeature> parse_scene_feature(std::string_view name) {
  for (size_t k = 0; k < feature_names.size(); ++k)
    if (feature_names[k] == name) return static_cast<SceneFeature>(k);
  return std::nullopt;
}

std::string scene_lacks_reason(SceneFeature f) {
  switch (f) {
    case SceneFeature::directional_lights:
      return "the scene has no directional lights";
    case SceneFeature::point_lights:
      return "the scene has no point lights";
    case SceneFeature::spot_lights:
      return "the scene has no spot lights";
    case SceneFeature::sphere_lights:
      return "the scene has no sphere lights";
    case SceneFeature::tube_lights:
      return "the scene has no tube lights";
    case SceneFeature::rectangle_lights:
      return "the scene has no rectangle lights";
    case SceneFeature::area_lights:
      return "the scene has no area lights";
    case SceneFeature::lights:
      return "the scene has no lights";
    case SceneFeature::shadow_casting_lights:
      return "no light in the scene casts shadows";
    case SceneFeature::local_shadow_casting_lights:
      return "no point, spot or area light in the scene casts shadows";
    case SceneFeature::environment_light:
      return "the scene has no environment light";
    case SceneFeature::irradiance_volumes:
      return "the scene has no irradiance volumes";
    case SceneFeature::reflection_probes:
      return "the scene has no reflection probes";
    case SceneFeature::glossy_materials:
      return "the scene has no glossy materials";
    case SceneFeature::thin_lens_camera:
      return "the camera is a pinhole (aperture 0): nothing is out of focus";
    case SceneFeature::baked_occlusion:
      return "no mesh in the scene carries baked occlusion";
    case SceneFeature::blend_materials:
      return "nothing in the scene is drawn with a BLEND (transparent) material";
    case SceneFeature::emissive_materials:
      return "nothing in the scene is drawn with an emissive material";
    case SceneFeature::planar_reflectors:
      return "the scene has no planar reflectors";
    case SceneFeature::count:
      break;
  }
  return "the scene lacks what this node needs";
}

bool SceneSummary::has(SceneFeature f) const {
  switch (f) {
    case SceneFeature::directional_lights:
      return directional_lights > 0;
    case SceneFeature::point_lights:
      return point_lights > 0;
    case SceneFeature::spot_lights:
      return spot_lights > 0;
    case SceneFeature::sphere_lights:
      return sphere_lights > 0;
    case SceneFeature::tube_lights:
      return tube_lights > 0;
    case SceneFeature::rectangle_lights:
      return rectangle_lights > 0;
    case SceneFeature::area_lights:
      return sphere_lights + tube_lights + rectangle_lights > 0;
    case SceneFeature::lights:
      return directional_lights + point_lights + spot_lights + sphere_lights + tube_lights + rectangle_lights > 0;
    case SceneFeature::shadow_casting_lights:
      return shadows && directional_lights + point_lights > 0;
    case SceneFeature::local_shadow_casting_lights:
      return local_shadows && point_lights + spot_lights + sphere_lights + tube_lights + rectangle_lights > 0;
    case SceneFeature::environment_light:
      return environment;
    case SceneFeature::irradiance_volumes:
      return irradiance_volumes > 0;
    case SceneFeature::reflection_probes:
      return reflection_probes > 0;
    case SceneFeature::glossy_materials:
      return glossy_materials;
    case SceneFeature::thin_lens_camera:
      return aperture > 0;
    case SceneFeature::baked_occlusion:
      return baked_occlusion;
    case SceneFeature::blend_materials:
      return blend_materials;
    case SceneFeature::emissive_materials:
      return emissive_materials;
    case SceneFeature::planar_reflectors:
      return planar_reflectors > 0;
    case SceneFeature::count:
      break;
  }
  return false;
}

SceneSummary default_scene_summary() {
  return SceneSummary{};
}

std::optional<SceneSummary> scene_summary_from_json(const JsonValue& root, Diagnostics& diagnostics) {
  size_t errors_before = diagnostics.error_count();
  SceneSummary summary;
  summary.name.clear();  // named by the file unless it says otherwise
  if (!root.is_object()) {
    diagnostics.error(root.pos(), "",
                      std::string("expected a scene summary object, found ") + JsonValue::kind_name(root.kind()));
    return std::nullopt;
  }
  for (const auto& [key, value] : root.members()) {
    std::string pointer = json_pointer_append("", key);
    if (key == "format") {
      if (!value.is_string() || value.as_string() != "lumagraph-scene-summary/1")
        diagnostics.error(value.pos(), pointer, "expected \"lumagraph-scene-summary/1\"");
      continue;
    }
    if (key == "name") {
      if (value.is_string())
        summary.name = value.as_string();
      else
        diagnostics.error(value.pos(), pointer, "expected a string");
      continue;
    }
    bool is_section = false;
    for (const auto& f : fields()) is_section |= f.section == key;
    if (!is_section) {
      diagnostics.error(value.pos(), pointer,
                        "unknown key '" + key +
                            "'; expected format, name, lights, environment, probes, materials, occlusion or camera");
      continue;
    }
    if (!value.is_object()) {
      diagnostics.error(value.pos(), pointer,
                        std::string("expected an object, found ") + JsonValue::kind_name(value.kind()));
      continue;
    }
    for (const auto& [sub, sub_value] : value.members()) {
      std::string sub_pointer = json_pointer_append(pointer, sub);
      const Field* field = nullptr;
      std::string known;
      for (const auto& f : fields()) {
        if (f.section != key) continue;
        if (f.key == sub) field = &f;
        known += (known.empty() ? "" : ", ") + std::string(f.key);
      }
      if (!field) {
        diagnostics.error(sub_value.pos(), sub_pointer, "unknown key '" + sub + "' in " + key + "; expected " + known);
        continue;
      }
      std::string expected;
      if (!field->read(sub_value, summary, expected))
        diagnostics.error(sub_value.pos(), sub_pointer, "expected " + expected);
    }
  }
  if (!root.find("format")) diagnostics.error(root.pos(), "", "missing \"format\": \"lumagraph-scene-summary/1\"");
  if (diagnostics.error_count() > errors_before) return std::nullopt;
  return summary;
}

std::optional<SceneSummary> load_scene_summary(const std::string& path, Diagnostics& diagnostics) {
  auto root = read_json_file(path, diagnostics);
  if (!root) return std::nullopt;
  return scene_summary_from_json(*root, diagnostics);
}

}  // namespace lg
