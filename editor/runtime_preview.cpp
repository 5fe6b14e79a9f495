#include "editor/runtime_preview.h"

#include <algorithm>
#include <exception>

#include "api/renderer.h"
#include "api/world_loading.h"
#include "graph/graph_io.h"
#include "nodes/raytrace/world_mesh.h"
#include "runtime/gpu/format.h"
#include "runtime/scene/default_world.h"
#include "runtime/scene/make_scene_view.h"

namespace lg::editor {
namespace {

// The resource the plan made for `port`: through the graph output graph_showing() added, which
// also follows a bypassed node to the resource it forwards.
const std::string& port_resource(const Plan& plan, const PreviewPort& port) {
  const std::string text = port.port.text();
  for (const PlanOutput& o : plan.outputs)
    if (o.node < 0 && o.port == text && port.component < int(o.resources.size()))
      return plan.resources[o.resources[port.component]].desc.name;
  throw std::runtime_error("the plan has no resource for " + port.name);
}

// texture2d:ldr (rgba8) holds sRGB values; four float or sRGB channels are linear light; the
// rest (normals, depth, masks, motion, lookup tables) are data.
PreviewEncoding preview_encoding(const FormatInfo& format) {
  if (format.channels < 4 || format.encoding == TexelEncoding::snorm8 ||
      format.encoding == TexelEncoding::unorm10_10_10_2)
    return PreviewEncoding::data;
  return format.encoding == TexelEncoding::unorm8 ? PreviewEncoding::display : PreviewEncoding::colour;
}

}  // namespace

Graph graph_showing(Graph graph, const PreviewPort& port) {
  const auto same = [&](const GraphOutput& o) { return o.port.text() == port.port.text(); };
  if (!port.name.empty() && std::none_of(graph.outputs.begin(), graph.outputs.end(), same))
    graph.outputs.push_back({port.port, {}});
  return graph;
}

RuntimePreview::RuntimePreview(const std::string& scene, const std::vector<std::string>& asset_roots)
    : scene_name_(scene.empty() ? "<default world>" : scene) {
  try {
    world_ = std::make_unique<World>(scene.empty() ? default_world()
                                                   : load_world(scene, renderer_world_options(scene, asset_roots)));
  } catch (const std::exception& e) {
    load_error_ = e.what();
  }
}
RuntimePreview::~RuntimePreview() = default;

SceneSummary RuntimePreview::scene_summary() const {
  return world_ ? make_scene_view(*world_, 16.0f / 9.0f).summary() : default_scene_summary();
}

PreviewImage RuntimePreview::render(const Graph& graph, QSize size, const PreviewPort& port, QString* error) {
  if (!world_) {
    *error = QString::fromStdString(load_error_);
    return {};
  }
  try {
    if (!renderer_) renderer_ = std::make_unique<Renderer>();
    // An unchanged graph keeps its executor: its kernels (a dynamic volume's probes) go on.
    Graph shown = graph_showing(graph, port);
    Graph unplaced = shown;
    unplaced.editor = JsonValue::object();
    std::string text = unplaced.file + '\n' + graph_to_text(unplaced);
    if (text != graph_text_) {
      renderer_->set_graph(std::move(shown));
      graph_text_ = std::move(text);
    }
    const FrameSize frame{uint32_t(std::max(size.width(), 16)), uint32_t(std::max(size.height(), 16))};
    const FrameStats& stats = renderer_->render(*world_, frame);
    Executor& executor = renderer_->executor();
    const std::string& name =
        port.name.empty() ? executor.output_resource("main") : port_resource(executor.plan(), port);
    const LoweredResource& desc = executor.plan().resources[executor.resource_index(name)].desc;
    if (desc.kind == ResourceKind::buffer) throw std::runtime_error("no image preview for buffers (" + name + ")");
    PreviewImage image;
    for (const PassStats& pass : stats.passes) image.pass_ms.emplace_back(pass.name, pass.cached ? -1.0 : pass.gpu_ms);
    image.width = int(desc.width);
    image.height = int(desc.height);
    image.rgba = executor.read_image(name);                   // mip 0, layer 0
    image.rgba.resize(size_t(desc.width) * desc.height * 4);  // a 3D texture's first slice
    const FormatInfo& format = format_info(desc.format);
    image.channels = int(format.channels);
    image.encoding = preview_encoding(format);
    image.probes = live_probes(graph);
    if (desc.kind == ResourceKind::cube) image.note = QStringLiteral("face +X of %1").arg(QString::fromStdString(name));
    if (desc.kind == ResourceKind::texture3d)
      image.note = QStringLiteral("slice 0 of %1 of %2").arg(desc.layers).arg(QString::fromStdString(name));
    return image;
  } catch (const std::exception& e) {
    graph_text_.clear();  // the next request sets the graph again
    *error = QString::fromStdString(e.what());
    return {};
  }
}

LiveProbes RuntimePreview::live_probes(const Graph& graph) {
  if (!geometry_hash_) geometry_hash_ = world_mesh_hash(make_world_mesh(renderer_->scene_view()));
  ProbeFileHeader identity;
  identity.scene = scene_name_;
  identity.graph = graph.file.empty() ? "<unsaved graph>" : graph.file;
  identity.geometry_hash = *geometry_hash_;
  return probes_.collect(renderer_->executor(), identity);
}

}  // namespace lg::editor
