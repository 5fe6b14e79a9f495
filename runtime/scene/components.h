// The components an entity of the world (world.h) may have. Lights and cameras live in their
// entity's local frame: cameras, directional, spot and rectangle lights aim down local -Z
// (up is +Y; a rectangle spans local X and Y), tubes lie along local X. Colours are linear Rec.709;
// `intensity` multiplies `color` and has the unit of the matching field of scene_view.h.
#pragma once

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <string>

#include "runtime/scene/entity.h"

namespace lg {

struct Name {
  std::string value;
};

struct Transform {
  glm::vec3 position{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z: identity
  glm::vec3 scale{1.0f};
  Entity parent{};  // null: the world's frame; else relative to the parent's Transform

  glm::mat4 local_matrix() const;
};

// The rotation that turns local -Z toward `direction` with local +Y as close to `up` as it goes.
glm::quat look_rotation(glm::vec3 direction, glm::vec3 up = {0.0f, 1.0f, 0.0f});

struct Camera {
  float vertical_fov = 0.8727f;  // radians (50 degrees)
  float near_plane = 0.05f;      // metres; the far plane is at infinity
  float aperture = 0.0f;         // lens diameter in metres; 0 is a pinhole
  float focus_distance = 5.0f;   // metres
};

struct MeshRenderer {
  int mesh = -1;      // index into World::meshes()
  int material = -1;  // index into World::materials(), or -1 for the default material
  // Whether reflection probes' captures see the mesh: off for objects inside a probe's proxy
  // that the proxy does not model (docs/reflection-probes.md).
  bool captured_by_probes = true;
  // The mesh's plane in its own space (n, w: n . p + w = 0) where the entity is a planar
  // reflector (gi.planar_reflection, docs/planar-reflections.md); nullopt for the rest.
  std::optional<glm::vec4> reflector_plane{};
};

struct DirectionalLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // irradiance, W/m^2
  float angular_radius = 0.00465f;
  bool casts_shadows = true;
};

struct PointLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // W/sr
  float range = 0.0f;      // 0: no cut-off
  bool casts_shadows = true;
};

// A point light limited to a cone about local -Z, as glTF's KHR_lights_punctual spot: full
// intensity within `inner_cone_angle` of the axis, falling to 0 at `outer_cone_angle`.
struct SpotLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;               // W/sr, on the axis
  float range = 0.0f;                   // 0: no cut-off
  float inner_cone_angle = 0.0f;        // radians from the axis, 0 to outer_cone_angle
  float outer_cone_angle = 0.7853982f;  // radians from the axis, up to pi/2 (glTF's default pi/4)
  bool casts_shadows = true;
};

struct SphereLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // radiance, W/(m^2 sr)
  float radius = 0.1f;
  bool casts_shadows = true;
};

struct TubeLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // radiance, W/(m^2 sr)
  float length = 1.0f;     // of the segment, along local X, centred on the entity
  float radius = 0.05f;
  bool casts_shadows = true;
};

struct RectLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;             // radiance, W/(m^2 sr)
  float width = 1.0f, height = 1.0f;  // along local X and Y
  bool two_sided = false;
  bool casts_shadows = true;
};

struct EnvironmentLight {
  std::string path;  // an .hdr or .exr file; empty: the procedural sky
  float intensity = 1.0f;
};

struct IrradianceVolume {
  glm::vec3 size{1.0f};  // of the box, in the local frame, centred on the entity
  glm::ivec3 probe_counts{4};
};

// A captured reflection probe (gi.reflection_capture, docs/reflection-probes.md), its cube taken
// at the entity's origin. The influence volume (box or sphere, centred on the entity) says
// where surfaces use it, fading out over `blend` metres inside its boundary; the parallax
// proxy (box or sphere, in the entity's frame, `proxy_offset` from its origin) is the shape the
// reflection ray is intersected with to find what the cube saw in that direction.
enum class ProbeShape : uint8_t { box, sphere };

struct ReflectionProbe {
  ProbeShape influence = ProbeShape::sphere;
  glm::vec3 extent{1.0f};  // box: half its size along each local axis
  float radius = 1.0f;     // sphere
  float blend = 0.0f;      // metres inside the influence boundary over which the weight falls to 0
  ProbeShape proxy = ProbeShape::sphere;
  glm::vec3 proxy_extent{1.0f};
  float proxy_radius = 1.0f;
  glm::vec3 proxy_offset{0.0f};
};

struct PostProcessSettings {
  float exposure = 0.0f;  // EV added to the camera's exposure
};

}  // namespace lg
