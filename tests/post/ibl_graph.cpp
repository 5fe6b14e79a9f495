#include "tests/post/ibl_graph.h"

#include <stdexcept>
#include <string>

#include "graph/graph_io.h"

namespace lg::test {

Graph ibl_graph(std::string_view dof_params) {
  std::string text = R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "sky", "type": "env.sky" },
      { "id": "sh", "type": "env.sh_project", "params": { "order": 2, "convolve_cosine": true } },
      { "id": "specular", "type": "env.specular_prefilter" }, { "id": "dfg", "type": "env.brdf_lut" },
      { "id": "light", "type": "lighting.deferred" }, { "id": "ibl", "type": "lighting.ibl" })";
  if (!dof_params.empty())
    text += R"(, { "id": "dof", "type": "post.dof", "params": )" + std::string(dof_params) + " }";
  text += R"( ], "links": [
      { "from": "sky.cube", "to": "sh.env" }, { "from": "sky.cube", "to": "specular.env" },
      { "from": "gbuf.gbuffer", "to": "light.gbuffer" }, { "from": "gbuf.gbuffer", "to": "ibl.gbuffer" },
      { "from": "light.color", "to": "ibl.direct" }, { "from": "sh.sh", "to": "ibl.sh" },
      { "from": "specular.specular", "to": "ibl.specular" }, { "from": "dfg.lut", "to": "ibl.brdf_lut" })";
  if (!dof_params.empty())
    text += R"(, { "from": "ibl.color", "to": "dof.color" }, { "from": "gbuf.gbuffer", "to": "dof.gbuffer" })";
  text += std::string(R"( ], "outputs": [ )") + (dof_params.empty() ? "" : R"("dof.color", )") + R"("ibl.color" ] })";
  Diagnostics d("ibl-graph.json");
  std::optional<Graph> graph = parse_graph_text(text, d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

}  // namespace lg::test
