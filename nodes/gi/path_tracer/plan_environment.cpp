// The environment of a plan for the CPU tracers (plan_environment.h).
#include "nodes/gi/path_tracer/plan_environment.h"

#include <cstdio>

#include "nodes/common/node_params.h"
#include "nodes/env/common/equirect.h"
#include "runtime/image/image_file.h"

namespace lg {

PathEnvironment plan_environment(const Plan& plan, bool scene_has_environment, const char* who) {
  if (!scene_has_environment) return PathEnvironment::none();
  for (const PlanNode& node : plan.nodes) {
    if (node.state != NodeState::Kind::active) continue;
    if (node.type == "env.load") {
      ImageData image = load_image(param_string(node, "path"));
      const uint64_t non_finite = sanitize_equirect(image.rgba, param_number(node, "intensity"));
      if (non_finite)
        std::fprintf(stderr, "%s: %llu non-finite texels of %s replaced by 0\n", who,
                     static_cast<unsigned long long>(non_finite), param_string(node, "path").c_str());
      return PathEnvironment::image(Equirect{image.width, image.height, std::move(image.rgba)});
    }
    if (node.type == "env.sky")
      return PathEnvironment::sky({glm::dvec3(param_float3(node, "sun_direction")), param_number(node, "sun_intensity"),
                                   param_number(node, "turbidity")});
  }
  return PathEnvironment::none();
}

bool plan_culls_backfaces(const Plan& plan, bool fallback) {
  for (const PlanNode& node : plan.nodes)
    if (node.type == "scene.gbuffer" && node.state == NodeState::Kind::active)
      return param_bool(node, "cull_backfaces");
  return fallback;
}

}  // namespace lg
