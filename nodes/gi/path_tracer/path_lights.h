// The SceneView's lights as the path tracer samples them and meets them (the raster path's
// definitions, nodes/lighting/deferred/README.md): directional lights as distant disks of their
// angular radius (radiance E / (pi sin^2 a); a delta direction at radius 0), point and spot
// lights as deltas with the deferred node's range window (spots with glTF's cone falloff), and sphere, tube (capsule)
// and rectangle lights as uniform Lambertian emitters. Like in the raster path, these lights are not geometry: they
// cast no shadow and the camera does not see them; a ray that crosses one collects its radiance
// and goes on. Each light is sampled on its own (next-event estimation): spheres and distant
// disks by their cone of directions, capsules and rectangles by area.
#pragma once

#include <cstddef>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

// One light's answer toward a point: the direction to it, how far the shadow ray goes, and the
// radiance over the solid-angle density of the sample (pdf > 0), or the irradiance a delta light
// (pdf = 0) gives a surface facing it.
struct LightSample {
  glm::dvec3 direction;
  double distance = 0.0;  // infinite for distant lights
  glm::dvec3 weight{0.0};
  double pdf = 0.0;
};

// A light a ray crosses: its radiance and the density its own sampler has for that direction.
struct LightCrossing {
  glm::dvec3 radiance;
  double pdf = 0.0;
};

class PathLights {
 public:
  // `distant_disks` adds distant emitters beyond the view's directional lights (the sky's sun):
  // each {direction toward it, angular radius, radiance}.
  struct DistantDisk {
    glm::dvec3 toward;
    double angular_radius = 0.0;
    glm::dvec3 radiance;
  };
  explicit PathLights(const SceneView& view, std::vector<DistantDisk> distant_disks = {});

  size_t count() const { return lights_.size(); }
  // Whether light i belongs to the view's lights (else it is part of the environment).
  bool is_scene_light(size_t i) const { return lights_[i].scene_light; }
  // Light i sampled from point p for a point u of [0, 1)^2; nullopt when it sends p nothing.
  std::optional<LightSample> sample(size_t i, glm::dvec3 p, glm::dvec2 u) const;
  // Calls f(light index, crossing) for every light the ray from `origin` along unit `direction`
  // crosses within (0, t_max]; distant lights only when t_max is infinite (the ray escaped).
  void each_crossed(glm::dvec3 origin, glm::dvec3 direction, double t_max,
                    const std::function<void(size_t, const LightCrossing&)>& f) const;

 private:
  enum class Kind { distant, point, sphere, tube, rect };
  struct Light {
    Kind kind;
    bool scene_light = true;
    glm::dvec3 radiance{0.0};           // point: intensity (W/sr); distant: the disk's radiance or, at
                                        // radius 0, the irradiance
    // distant: toward; point: position and, for a spot, its axis b (the way light travels);
    // sphere, rect: centre; tube: ends a and b; rect: half axes b and c
    glm::dvec3 a{0.0}, b{0.0}, c{0.0};
    double size = 0.0;  // distant: 1 - cos of the angular radius; point: range; sphere, tube: radius
    double area = 0.0;  // tube, rect
    double cone_scale = 0.0, cone_offset = 1.0;  // point: glTF's spot ramp in cos about b (none: 1)
    bool two_sided = false;
  };
  std::optional<LightSample> sample_distant(const Light& l, glm::dvec2 u) const;
  std::optional<LightSample> sample_sphere(const Light& l, glm::dvec3 p, glm::dvec2 u) const;
  std::optional<LightSample> sample_tube(const Light& l, glm::dvec3 p, glm::dvec2 u) const;
  std::optional<LightSample> sample_rect(const Light& l, glm::dvec3 p, glm::dvec2 u) const;

  std::vector<Light> lights_;
};

}  // namespace lg
