#include "nodes/gi/irradiance_volume/probe_bake_key.h"

#include <cstring>
#include <glm/mat4x4.hpp>
#include <string>

#include "graph/fnv1a.h"

namespace lg {
namespace {

// FNV-1a over values one by one (never a struct's bytes: padding is not part of a light).
struct Hasher {
  uint64_t h = fnv1a_basis;
  void bytes(const void* data, size_t size) { h = fnv1a(data, size, h); }
  void add(float v) { bytes(&v, sizeof v); }
  void add(bool v) { add(v ? 1.0f : 0.0f); }
  void add(uint64_t v) { bytes(&v, sizeof v); }
  void add(int v) { bytes(&v, sizeof v); }
  void add(const std::string& s) { add(uint64_t(s.size())), bytes(s.data(), s.size()); }
  void add(glm::vec3 v) { add(v.x), add(v.y), add(v.z); }
  void add(glm::ivec3 v) { add(v.x), add(v.y), add(v.z); }
  void add(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) add(m[c][r]);
  }
  template <class... T>
  void all(const T&... v) {
    (add(v), ...);
  }
};

void add_volumes(Hasher& h, const SceneView& s) {
  h.add(uint64_t(s.irradiance_volumes.size()));
  for (const auto& v : s.irradiance_volumes) h.all(v.world, v.size, v.probe_counts);
}

// Everything light transport in the scene depends on: assets, draws, lights, environment.
void add_transport(Hasher& h, const SceneView& s) {
  h.add(s.version);
  h.add(uint64_t(s.draws.size()));
  for (const DrawItem& d : s.draws) h.all(d.mesh, d.material, d.world);
  for (const auto& l : s.directional_lights) h.all(l.direction, l.irradiance, l.angular_radius);
  for (const auto& l : s.point_lights) h.all(l.position, l.intensity, l.range);
  for (const auto& l : s.spot_lights)
    h.all(l.position, l.direction, l.intensity, l.range, l.inner_cone_angle, l.outer_cone_angle);
  for (const auto& l : s.sphere_lights) h.all(l.center, l.radius, l.radiance);
  for (const auto& l : s.tube_lights) h.all(l.end0, l.end1, l.radius, l.radiance);
  for (const auto& l : s.rect_lights) h.all(l.center, l.half_x, l.half_y, l.radiance, l.two_sided);
  // The counts separate lights of one kind from the next kind's.
  h.all(int(s.directional_lights.size()), int(s.point_lights.size()), int(s.spot_lights.size()),
        int(s.sphere_lights.size()), int(s.tube_lights.size()), int(s.rect_lights.size()));
  h.all(s.has_environment, s.environment.path, s.environment.intensity);
}

}  // namespace

uint64_t probe_bake_key(const SceneView& s) {
  Hasher h;
  add_transport(h, s);
  add_volumes(h, s);
  return h.h;
}

uint64_t reflection_capture_key(const SceneView& s) {
  Hasher h;
  add_transport(h, s);
  for (const DrawItem& d : s.draws) h.add(d.captured_by_probes);
  h.add(uint64_t(s.reflection_probes.size()));
  for (const auto& r : s.reflection_probes) {
    const ReflectionProbe& p = r.probe;
    h.all(r.world, int(p.influence), p.extent, p.radius, p.blend, int(p.proxy), p.proxy_extent, p.proxy_radius,
          p.proxy_offset);
  }
  return h.h;
}

uint64_t probe_volume_key(const SceneView& s) {
  Hasher h;
  add_volumes(h, s);
  return h.h;
}

}  // namespace lg
