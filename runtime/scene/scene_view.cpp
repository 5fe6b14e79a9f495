#include "runtime/scene/scene_view.h"

#include <stdexcept>

namespace lg {

const MeshData& SceneView::mesh_of(const DrawItem& draw) const {
  if (draw.mesh < 0 || static_cast<size_t>(draw.mesh) >= meshes.size())
    throw std::invalid_argument("a draw names mesh " + std::to_string(draw.mesh) + ", but the scene has " +
                                std::to_string(meshes.size()));
  const auto& mesh = meshes[static_cast<size_t>(draw.mesh)];
  if (!mesh) throw std::invalid_argument("a draw names mesh " + std::to_string(draw.mesh) + ", which is null");
  return *mesh;
}

const PbrMaterial& SceneView::material_of(const DrawItem& draw) const {
  static const PbrMaterial default_material;
  const bool valid = draw.material >= 0 && static_cast<size_t>(draw.material) < materials.size();
  return valid ? materials[static_cast<size_t>(draw.material)] : default_material;
}

SceneSummary SceneView::summary() const {
  SceneSummary s;
  s.name = name;
  s.directional_lights = static_cast<int>(directional_lights.size());
  s.point_lights = static_cast<int>(point_lights.size());
  s.spot_lights = static_cast<int>(spot_lights.size());
  s.sphere_lights = static_cast<int>(sphere_lights.size());
  s.tube_lights = static_cast<int>(tube_lights.size());
  s.rectangle_lights = static_cast<int>(rect_lights.size());
  s.shadows = false;
  for (const auto& d : directional_lights) s.shadows |= d.casts_shadows;
  s.local_shadows = false;
  for (const auto& l : point_lights) s.local_shadows |= l.casts_shadows;
  for (const auto& l : spot_lights) s.local_shadows |= l.casts_shadows;
  for (const auto& l : sphere_lights) s.local_shadows |= l.casts_shadows;
  for (const auto& l : tube_lights) s.local_shadows |= l.casts_shadows;
  for (const auto& l : rect_lights) s.local_shadows |= l.casts_shadows;
  s.environment = has_environment;
  s.irradiance_volumes = int(irradiance_volumes.size());
  s.reflection_probes = int(reflection_probes.size());
  s.planar_reflectors = int(planar_reflectors.size());
  // Only the materials something is drawn with.
  s.glossy_materials = false;
  for (const auto& d : draws) {
    const PbrMaterial& m = material_of(d);
    // A metallic-roughness texture can only lower the roughness factor and raise no metal above it.
    s.glossy_materials |= m.roughness < 0.9f || m.metalness > 0.0f || m.metallic_roughness_texture.texture >= 0;
    s.blend_materials |= m.alpha_mode == AlphaMode::blend;
    // The emissive texture multiplies the factor, so a factor of 0 emits nothing.
    s.emissive_materials |= m.emissive.r > 0.0f || m.emissive.g > 0.0f || m.emissive.b > 0.0f;
    s.baked_occlusion |=
        d.mesh >= 0 && size_t(d.mesh) < meshes.size() && meshes[size_t(d.mesh)] && meshes[size_t(d.mesh)]->occlusion;
  }
  s.aperture = camera.aperture;
  s.focus_distance = camera.focus_distance;
  return s;
}

}  // namespace lg
