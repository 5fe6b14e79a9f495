#include "tests/occlusion/ao_render.h"

#include <filesystem>
#include <stdexcept>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/load_world.h"

namespace lg::test {

Graph occlusion_graph(const std::string& node) {
  const bool gtao = node.find("occlusion.gtao") != std::string::npos;
  const std::string text = R"({ "format": "lumagraph/1", "name": "occlusion",
    "nodes": [ { "id": "gbuf", "type": "scene.gbuffer" }, )" +
                           node + R"( ],
    "links": [ { "from": "gbuf.gbuffer", "to": "ao.gbuffer" })" +
                           (gtao ? R"(, { "from": "ao.ao", "to": "ao.history" })" : "") + R"( ],
    "outputs": [ "ao.ao" ] })";
  Diagnostics d("occlusion.json");
  std::optional<Graph> graph = parse_graph_text(text, d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

AoRender render_occlusion(const World& world, uint32_t width, uint32_t height, const std::string& node,
                          const AoRenderOptions& options) {
  RendererOptions renderer_options;
  renderer_options.device.validation = options.validation;
  renderer_options.alias = false;  // the G-buffer is read back after the frame
  Renderer renderer(renderer_options);
  renderer.set_graph(occlusion_graph(node));
  AoRender out;
  for (int f = 0; f < options.frames; ++f) {
    const FrameStats& stats = renderer.render(world, {width, height});
    double ms = 0;
    for (const PassStats& pass : stats.passes)
      if (pass.name.rfind("ao/", 0) == 0) ms += pass.gpu_ms;
    out.ao_gpu_ms.push_back(ms);
    out.frame_gpu_ms.push_back(stats.gpu_ms);
    if (f == 0) out.first_ao = renderer.executor().read_image("ao.ao");
  }
  out.last_ao = renderer.executor().read_image("ao.ao");
  if (node.find("occlusion.gtao") != std::string::npos || node.find("occlusion.bake") != std::string::npos)
    out.bent_normals = renderer.executor().read_image("ao.bent_normals");
  out.gbuffer.width = width;
  out.gbuffer.height = height;
  const std::vector<float> depth = renderer.executor().read_image("gbuf.gbuffer.depth");
  for (size_t i = 0; i < depth.size(); i += 4) out.gbuffer.depth.push_back(depth[i]);
  out.gbuffer.normal = renderer.executor().read_image("gbuf.gbuffer.normal");
  out.view = renderer.scene_view();
  out.validation_messages = renderer.context().take_validation_messages().size();
  return out;
}

World load_example_world(const std::string& name) {
  const std::filesystem::path source(LUMAGRAPH_SOURCE_DIR);
  WorldLoadOptions options;
  options.asset_roots.roots = {(source / "examples" / "worlds").string(), (source / ".." / "shared" / "data").string()};
  return load_world((source / "examples" / "worlds" / (name + ".json")).string(), options);
}

bool have_bunny() {
  return std::filesystem::exists(std::filesystem::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data" / "mesh" /
                                 "bunny.obj");
}

}  // namespace lg::test
