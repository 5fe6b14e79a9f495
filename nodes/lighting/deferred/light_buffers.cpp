// LightBuffers: the scene's lights in the layouts of shaders/lights.glsl (vec4 members only, so
// std140 and std430 agree).
#include "nodes/lighting/deferred/light_buffers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lg {
namespace {

struct GpuDirectional {
  glm::vec4 direction, irradiance;
};
struct GpuPoint {
  glm::vec4 position_range, intensity;
};
struct GpuSpot {
  glm::vec4 position_range, direction_angle_scale, intensity_angle_offset, shadow;
};
struct GpuShadowView {
  glm::mat4 clip_from_world;
  glm::vec4 tile;
};
struct GpuSphere {
  glm::vec4 center_radius, radiance;
};
struct GpuTube {
  glm::vec4 end0_radius, end1, radiance;
};
struct GpuRect {
  glm::vec4 center_two_sided, half_x, half_y, radiance;
};

GpuSpot gpu_spot(const SpotLightData& l, int first_view, int views) {
  const glm::vec2 ramp = spot_ramp(l);
  return {glm::vec4(l.position, l.range), glm::vec4(l.direction, ramp.x), glm::vec4(l.intensity, ramp.y),
          glm::vec4(float(first_view), float(views), 0.0f, 0.0f)};
}

// A list as its uniform block takes it: the block's whole size (the shaders declare
// LG_MAX_LIGHTS entries), the entries past the count unread.
template <typename T>
void write_list(HostBuffer& buffer, std::vector<T> lights, const char* kind) {
  if (lights.size() > kMaxLightsPerKind)
    throw std::runtime_error("at most " + std::to_string(kMaxLightsPerKind) + " " + kind +
                             " lights are shaded a frame (the light lists are uniform blocks); this frame has " +
                             std::to_string(lights.size()) + " (those that reach the view where the node culls)");
  lights.resize(kMaxLightsPerKind);
  buffer.write(lights);
}

}  // namespace

int shadow_caster(const SceneView& scene) {
  for (size_t i = 0; i < scene.directional_lights.size(); ++i)
    if (scene.directional_lights[i].casts_shadows) return static_cast<int>(i);
  return -1;
}

LightBuffers::LightBuffers(Context& gpu, const std::string& id)
    : constants(gpu, id + " constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      directional_(gpu, id + " directional lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      points_(gpu, id + " point lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      spots_(gpu, id + " spot lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      spheres_(gpu, id + " sphere lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      tubes_(gpu, id + " tube lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      rects_(gpu, id + " rectangle lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      shadow_views_(gpu, id + " local shadow views", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      ltc_(gpu, id + " LTC table", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT) {
  ltc_.write_value(ltc_table_texels());
}

void LightBuffers::write_lights(const SceneView& scene, int caster, const LocalShadows& local,
                                LightConstants& constants_out) {
  std::vector<GpuDirectional> directional;
  for (size_t i = 0; i < scene.directional_lights.size(); ++i) {
    const auto& l = scene.directional_lights[i];
    directional.push_back({glm::vec4(l.direction, int(i) == caster ? 1.0f : 0.0f), glm::vec4(l.irradiance, 0.0f)});
  }
  std::vector<GpuPoint> points;
  for (size_t i = 0; i < scene.point_lights.size(); ++i) {
    const auto& l = scene.point_lights[i];
    points.push_back({glm::vec4(l.position, l.range), glm::vec4(l.intensity, float(local.point_first_view[i]))});
  }
  std::vector<GpuSpot> spots;
  for (size_t i = 0; i < scene.spot_lights.size(); ++i)
    spots.push_back(gpu_spot(scene.spot_lights[i], local.spot_first_view[i], local.spot_view_count[i]));
  std::vector<GpuShadowView> views;
  for (const LocalShadowView& v : local.views)
    views.push_back({v.clip_from_world, glm::vec4(glm::vec2(v.origin), float(v.size), v.texel_per_distance)});
  std::vector<GpuSphere> spheres;
  for (size_t i = 0; i < scene.sphere_lights.size(); ++i) {
    const auto& l = scene.sphere_lights[i];
    spheres.push_back({glm::vec4(l.center, l.radius), glm::vec4(l.radiance, float(local.sphere_first_view[i]))});
  }
  std::vector<GpuTube> tubes;
  for (size_t i = 0; i < scene.tube_lights.size(); ++i) {
    const auto& l = scene.tube_lights[i];
    tubes.push_back(
        {glm::vec4(l.end0, l.radius), glm::vec4(l.end1, float(local.tube_first_view[i])), glm::vec4(l.radiance, 0.0f)});
  }
  std::vector<GpuRect> rects;
  for (size_t i = 0; i < scene.rect_lights.size(); ++i) {
    const auto& l = scene.rect_lights[i];
    rects.push_back({glm::vec4(l.center, l.two_sided ? 1.0f : 0.0f), glm::vec4(l.half_x, 0.0f),
                     glm::vec4(l.half_y, 0.0f), glm::vec4(l.radiance, float(local.rect_first_view[i]))});
  }
  constants_out.counts[0] = uint32_t(directional.size());
  constants_out.counts[1] = uint32_t(points.size());
  constants_out.counts[2] = uint32_t(spheres.size());
  constants_out.counts[3] = uint32_t(tubes.size());
  constants_out.counts2[0] = uint32_t(rects.size());
  constants_out.counts2[1] = uint32_t(spots.size());
  write_list(directional_, std::move(directional), "directional");
  write_list(points_, std::move(points), "point");
  write_list(spots_, std::move(spots), "spot");
  write_list(spheres_, std::move(spheres), "sphere");
  write_list(tubes_, std::move(tubes), "tube");
  write_list(rects_, std::move(rects), "rectangle");
  if (views.size() > kMaxShadowViews)
    throw std::runtime_error("at most " + std::to_string(kMaxShadowViews) +
                             " local shadow views are drawn a frame (a uniform block); this frame has " +
                             std::to_string(views.size()));
  views.resize(kMaxShadowViews);
  shadow_views_.write(views);
}

void LightBuffers::add_constants(std::vector<DescriptorWrite>& writes) const {
  writes.push_back(uniform_buffer(0, constants.handle()));
}

void LightBuffers::add_direct_lists(std::vector<DescriptorWrite>& writes) const {
  writes.push_back(uniform_buffer(11, directional_.handle()));
  writes.push_back(uniform_buffer(12, points_.handle()));
  writes.push_back(uniform_buffer(13, spots_.handle()));
}

void LightBuffers::add_shadow_views(std::vector<DescriptorWrite>& writes) const {
  writes.push_back(uniform_buffer(15, shadow_views_.handle()));
}

void LightBuffers::add_area_lists(std::vector<DescriptorWrite>& writes) const {
  writes.push_back(uniform_buffer(16, spheres_.handle()));
  writes.push_back(uniform_buffer(17, tubes_.handle()));
  writes.push_back(uniform_buffer(18, rects_.handle()));
  writes.push_back(uniform_buffer(22, ltc_.handle()));
}

glm::vec2 spot_ramp(const SpotLightData& light) {
  const float cos_outer = std::cos(light.outer_cone_angle);
  const float scale = 1.0f / std::max(0.001f, std::cos(light.inner_cone_angle) - cos_outer);
  return {scale, -cos_outer * scale};
}

}  // namespace lg
