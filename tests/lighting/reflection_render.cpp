#include "tests/lighting/reflection_render.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "graph/json_reader.h"
#include "nodes/gi/path_tracer/plan_environment.h"

namespace lg::test {
namespace {

double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) * 1e-3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

constexpr const char* kExample = LUMAGRAPH_SOURCE_DIR "/examples/reflections.json";
constexpr const char* kPlanarExample = LUMAGRAPH_SOURCE_DIR "/examples/planar-reflections.json";

GraphNode& node(Graph& graph, const std::string& id, const char* file) {
  for (GraphNode& n : graph.nodes)
    if (n.id == id) return n;
  throw std::runtime_error(std::string(file) + " has no node '" + id + "'");
}

// Sets every member of the JSON object text `{ members }` on `params`.
void set_params(JsonValue& params, const std::string& members, const std::string& who) {
  if (members.empty()) return;
  Diagnostics d(who);
  std::optional<JsonValue> parsed = read_json("{ " + members + " }", d);
  if (!parsed || !parsed->is_object())
    throw std::runtime_error(who + ": not JSON members: " + members + "\n" + d.to_string());
  for (const auto& [key, value] : parsed->members()) params.set(key, value);
}

bool uses_probes(ReflectionSource s) {
  return s == ReflectionSource::probes || s == ReflectionSource::ssr_with_probes ||
         s == ReflectionSource::planar_with_probes;
}
bool uses_ssr(ReflectionSource s) {
  return s == ReflectionSource::ssr || s == ReflectionSource::ssr_with_probes || s == ReflectionSource::planar_with_ssr;
}
bool uses_planar(ReflectionSource s) {
  return s == ReflectionSource::planar || s == ReflectionSource::planar_with_probes ||
         s == ReflectionSource::planar_with_ssr;
}

}  // namespace

const char* reflection_source_name(ReflectionSource source) {
  switch (source) {
    case ReflectionSource::environment:
      return "environment";
    case ReflectionSource::probes:
      return "probes";
    case ReflectionSource::ssr:
      return "ssr";
    case ReflectionSource::ssr_with_probes:
      return "ssr+probes";
    case ReflectionSource::planar:
      return "planar";
    case ReflectionSource::planar_with_probes:
      return "planar+probes";
    case ReflectionSource::planar_with_ssr:
      return "planar+ssr";
    case ReflectionSource::voxel:
      return "voxel";
  }
  return "?";
}

std::string config_label(const ReflectionConfig& c) {
  std::string label = reflection_source_name(c.source);
  if (uses_probes(c.source)) {
    if (!c.parallax) label += " no-parallax";
    if (c.face_size > 0) label += " face=" + std::to_string(c.face_size);
  }
  if (uses_ssr(c.source)) {
    if (c.max_steps > 0) label += " steps=" + std::to_string(c.max_steps);
    if (c.ssr_scale > 0 && c.ssr_scale < 1) label += " scale=" + std::to_string(c.ssr_scale).substr(0, 4);
  }
  if (uses_planar(c.source) && c.planar_scale > 0) label += " planar=" + std::to_string(c.planar_scale).substr(0, 4);
  if (c.source == ReflectionSource::voxel && c.voxel_scale > 0)
    label += " scale=" + std::to_string(c.voxel_scale).substr(0, 4);
  if (c.source == ReflectionSource::voxel && !c.voxel_sky) label += " sun-only";
  return label;
}

Graph reflection_graph(const ReflectionConfig& c) {
  const char* file = uses_planar(c.source) ? kPlanarExample : kExample;
  Diagnostics d(file);
  std::optional<Graph> loaded = load_graph_file(file, d);
  if (!loaded) throw std::runtime_error(d.to_string());
  Graph graph = std::move(*loaded);
  // The probes feed lighting.ibl directly or through the planar node.
  std::erase_if(graph.links, [&](const GraphLink& link) {
    return (link.from.text() == "probes.reflections" && !uses_probes(c.source)) ||
           (link.to.text() == "ibl.ssr" && !uses_ssr(c.source));
  });
  if (uses_planar(c.source) && c.planar_scale > 0)
    node(graph, "planar", file).params.set("resolution_scale", c.planar_scale);
  JsonValue& probes = node(graph, "probes", file).params;
  probes.set("parallax", c.parallax);
  if (c.face_size > 0) probes.set("face_size", c.face_size);
  set_params(probes, c.probe_params, "probe params");
  JsonValue& ssr = node(graph, "ssr", file).params;
  if (c.max_steps > 0) ssr.set("max_steps", c.max_steps);
  if (c.ssr_scale > 0) ssr.set("resolution_scale", c.ssr_scale);
  set_params(ssr, c.ssr_params, "ssr params");
  if (c.source == ReflectionSource::voxel) {
    GraphNode& voxel = graph.nodes.emplace_back();
    voxel.id = "voxel";
    voxel.type = "gi.voxel";
    if (c.voxel_scale > 0) voxel.params.set("resolution_scale", c.voxel_scale);
    auto link = [&graph](PortRef from, PortRef to) {
      GraphLink& l = graph.links.emplace_back();
      l.from = std::move(from);
      l.to = std::move(to);
    };
    link({"gbuf", "gbuffer"}, {"voxel", "gbuffer"});
    link({"voxel", "specular"}, {"ibl", "reflection_probes"});
    if (c.voxel_sky) link({"sh", "sh"}, {"voxel", "sh"});
  }
  return graph;
}

ReflectionFrame render_reflections(const World& world, uint32_t width, uint32_t height, const Graph& graph, int frames,
                                   bool validation) {
  RendererOptions options;
  options.device.validation = validation;
  options.alias = false;  // intermediate results are read back after the frame
  Renderer renderer(options);
  renderer.set_graph(graph);
  ReflectionFrame out;
  for (int f = 0; f < frames; ++f) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_ms();
    const FrameStats& stats = renderer.render(world, {width, height});
    out.frame_cpu_ms.push_back(process_cpu_ms() - cpu_start);
    out.frame_wall_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    double ms = 0;
    for (const PassStats& pass : stats.passes)
      if (pass.name.rfind("probes/", 0) == 0 || pass.name.rfind("planar/", 0) == 0 || pass.name.rfind("ssr/", 0) == 0 ||
          pass.name.rfind("voxel/", 0) == 0)
        ms += pass.gpu_ms;
    out.reflection_gpu_ms.push_back(ms);
    out.frame_gpu_ms.push_back(stats.gpu_ms);
  }
  Executor& executor = renderer.executor();
  out.direct = executor.read_image("light.color");
  out.lit = executor.read_image("ibl.color");
  out.material = executor.read_image("gbuf.gbuffer.material");
  for (const PlanNode& n : renderer.plan().nodes)
    if (n.id == "ssr" && n.state == NodeState::Kind::active) out.ssr = executor.read_image("ssr.reflections");
  out.environment = plan_environment(renderer.plan(), renderer.scene_view().has_environment, "reflection render");
  out.validation_messages = renderer.context().take_validation_messages().size();
  return out;
}

}  // namespace lg::test
