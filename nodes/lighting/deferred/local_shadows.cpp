#include "nodes/lighting/deferred/local_shadows.h"

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "runtime/scene/projection.h"

namespace lg {
namespace {

// A spot up to this wide (outer cone angle) fits one perspective view; wider ones would spread
// a single map's texels too thin at its edge, so they get a cube like a point light.
constexpr float max_single_view_angle = 1.0471976f;  // 60 degrees

uint32_t grid_columns(uint32_t budget) {
  return static_cast<uint32_t>(std::ceil(std::sqrt(6.0 * std::max(budget, 1u))));
}

// From `position` along unit `axis`, covering tan(half-angle) `tan_half` plus the margin.
LocalShadowView make_view(glm::vec3 position, glm::vec3 axis, float tan_half, uint32_t tile, glm::uvec2 origin) {
  const float widened = tan_half * float(tile) / float(tile - 2 * local_shadow_margin);
  const glm::vec3 up = std::abs(axis.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::mat4 view = glm::lookAt(position, position + axis, up);
  const glm::mat4 projection = reversed_z_infinite_perspective(2.0f * std::atan(widened), 1.0f, local_shadow_near);
  return {projection * view, origin, tile, 2.0f * widened / float(tile)};
}

}  // namespace

uint32_t local_shadow_tile_size(uint32_t atlas_size, uint32_t budget) {
  return atlas_size / grid_columns(budget);
}

LocalShadows no_local_shadows(const SceneView& scene) {
  LocalShadows out;
  out.point_first_view.assign(scene.point_lights.size(), -1);
  out.spot_first_view.assign(scene.spot_lights.size(), -1);
  out.spot_view_count.assign(scene.spot_lights.size(), 0);
  out.sphere_first_view.assign(scene.sphere_lights.size(), -1);
  out.tube_first_view.assign(scene.tube_lights.size(), -1);
  out.rect_first_view.assign(scene.rect_lights.size(), -1);
  return out;
}

LocalShadows plan_local_shadows(const SceneView& scene, uint32_t budget, uint32_t atlas_size) {
  LocalShadows out = no_local_shadows(scene);

  // A light that casts: where its map looks from, the spot it is (null: a cube), and the
  // entry of its list that gets its first view.
  struct Caster {
    float distance2;  // from the camera
    glm::vec3 position;
    const SpotLightData* spot;  // null: a cube
    int* first;
  };
  std::vector<Caster> casters;
  const glm::vec3 eye = scene.camera.position;
  auto add = [&](bool casts, glm::vec3 position, const SpotLightData* spot, int& first) {
    if (casts) casters.push_back({glm::dot(position - eye, position - eye), position, spot, &first});
  };
  for (size_t i = 0; i < scene.point_lights.size(); ++i)
    add(scene.point_lights[i].casts_shadows, scene.point_lights[i].position, nullptr, out.point_first_view[i]);
  for (size_t i = 0; i < scene.spot_lights.size(); ++i)
    add(scene.spot_lights[i].casts_shadows, scene.spot_lights[i].position, &scene.spot_lights[i],
        out.spot_first_view[i]);
  for (size_t i = 0; i < scene.sphere_lights.size(); ++i)
    add(scene.sphere_lights[i].casts_shadows, scene.sphere_lights[i].center, nullptr, out.sphere_first_view[i]);
  for (size_t i = 0; i < scene.tube_lights.size(); ++i) {
    const TubeLightData& l = scene.tube_lights[i];
    add(l.casts_shadows, 0.5f * (l.end0 + l.end1), nullptr, out.tube_first_view[i]);
  }
  // A rectangle emits into one hemisphere only, yet it gets all six faces: a face lies wholly
  // behind the rectangle only when the rectangle is aligned with the axes, and even then it
  // is one face of six, not worth a second way of indexing the views.
  for (size_t i = 0; i < scene.rect_lights.size(); ++i)
    add(scene.rect_lights[i].casts_shadows, scene.rect_lights[i].center, nullptr, out.rect_first_view[i]);
  // Ties keep the lists' order, so the choice is stable from frame to frame.
  std::stable_sort(casters.begin(), casters.end(),
                   [](const Caster& a, const Caster& b) { return a.distance2 < b.distance2; });
  if (casters.size() > budget) casters.resize(budget);

  const uint32_t columns = grid_columns(budget), tile = local_shadow_tile_size(atlas_size, budget);
  auto add_view = [&](glm::vec3 position, glm::vec3 axis, float tan_half) {
    const auto t = static_cast<uint32_t>(out.views.size());
    out.views.push_back(make_view(position, axis, tan_half, tile, glm::uvec2(t % columns, t / columns) * tile));
  };
  auto add_cube = [&](glm::vec3 position) {
    for (int axis = 0; axis < 3; ++axis)
      for (float sign : {1.0f, -1.0f}) {
        glm::vec3 direction(0.0f);
        direction[axis] = sign;
        add_view(position, direction, 1.0f);
      }
  };
  for (const Caster& c : casters) {
    *c.first = static_cast<int>(out.views.size());
    const SpotLightData* spot = c.spot;
    int views = 6;
    if (spot && spot->outer_cone_angle <= max_single_view_angle) {
      // A cone of angle 0 still gets a view a hundredth of a radian wide.
      add_view(spot->position, spot->direction, std::tan(std::max(spot->outer_cone_angle, 0.01f)));
      views = 1;
    } else {
      add_cube(c.position);
    }
    if (spot) out.spot_view_count[size_t(spot - scene.spot_lights.data())] = views;
  }
  return out;
}

}  // namespace lg
