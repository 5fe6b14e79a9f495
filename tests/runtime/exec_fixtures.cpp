#include "tests/runtime/exec_fixtures.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/plan_resources.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr std::string_view schemas[] = {
    R"({ "type": "test.fill", "doc": "Fills an image with its value.",
         "params": [ { "name": "value", "type": "float", "default": 0.25, "doc": "Red." } ],
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "doc": "Filled." } ],
         "passes": [ { "name": "fill", "queue": "compute", "uses": { "out.color": "storage_write" } } ] })",
    R"({ "type": "test.bake", "doc": "A static fill: cached across frames.", "static": true,
         "params": [ { "name": "value", "type": "float", "default": 0.5, "doc": "Red." } ],
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "doc": "Filled." } ],
         "passes": [ { "name": "fill", "queue": "compute", "uses": { "out.color": "storage_write" } } ] })",
    R"({ "type": "test.add", "doc": "Adds to red, reading through a sampler.",
         "params": [ { "name": "add", "type": "float", "default": 1, "doc": "Added." } ],
         "inputs": [ { "name": "src", "type": "texture2d:hdr", "doc": "Source." } ],
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "input:src", "doc": "Sum." } ],
         "passes": [ { "name": "add", "queue": "compute", "uses": { "in.src": "sampled", "out.color": "storage_write" } } ],
         "bypass": [ { "when": { "param": "add", "at_most": 0 }, "forward": { "color": "src" }, "reason": "adds nothing" } ] })",
    R"({ "type": "test.accumulate", "doc": "Last frame's result plus one.",
         "inputs": [ { "name": "history", "type": "texture2d:hdr", "history": true, "doc": "Last frame." } ],
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "doc": "Sum." } ],
         "passes": [ { "name": "accumulate", "queue": "compute",
                       "uses": { "in.history": "sampled", "out.color": "storage_write" } } ] })",
    R"({ "type": "test.two_pass", "doc": "Adds one twice, through an internal image.",
         "inputs": [ { "name": "src", "type": "texture2d:hdr", "doc": "Source." } ],
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "input:src", "doc": "Plus two." } ],
         "resources": [ { "name": "tmp", "type": "texture2d:hdr", "extent": "input:src", "doc": "Plus one." } ],
         "passes": [ { "name": "first", "queue": "compute", "uses": { "in.src": "storage_read", "tmp.tmp": "storage_write" } },
                     { "name": "second", "queue": "compute", "uses": { "tmp.tmp": "storage_read", "out.color": "storage_write" } } ] })",
    R"({ "type": "test.sh", "doc": "Writes a buffer of vec4.",
         "params": [ { "name": "order", "type": "int", "default": 2, "min": 1, "max": 4, "doc": "SH order." },
                     { "name": "value", "type": "float", "default": 3, "doc": "Second component." } ],
         "outputs": [ { "name": "sh", "type": "sh", "sh_order": "param:order", "doc": "(order + 1)^2 vec4." } ],
         "passes": [ { "name": "write", "queue": "compute", "uses": { "out.sh": "buffer_write" } } ] })",
    R"({ "type": "test.raster", "doc": "Draws the scene's first mesh.",
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "doc": "Drawn." } ],
         "passes": [ { "name": "draw", "queue": "graphics", "uses": { "out.color": "attachment_write" } } ] })",
    R"({ "type": "test.lit", "doc": "A fill, and a pass that only scenes with area lights keep.",
         "params": [ { "name": "value", "type": "float", "default": 0.75, "doc": "Red." } ],
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "doc": "Filled." } ],
         "passes": [ { "name": "direct", "queue": "compute", "uses": { "out.color": "storage_write" } },
                     { "name": "area", "queue": "compute", "needs": "area_lights",
                       "uses": { "out.color": "storage_read_write" } } ] })",
    R"({ "type": "test.boom", "doc": "Its kernel throws.",
         "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "doc": "Never written." } ],
         "passes": [ { "name": "explode", "queue": "compute", "uses": { "out.color": "storage_write" } } ] })",
    R"({ "type": "test.display", "doc": "A result of the frame.", "output": true,
         "params": [ { "name": "name", "type": "string", "default": "main", "doc": "Looked up by." } ],
         "inputs": [ { "name": "color", "type": "texture2d:*", "doc": "Shown." } ] })",
};

const Registry& test_registry() {
  static const Registry registry = [] {
    Registry r;
    Diagnostics d("test schema");
    for (std::string_view text : schemas)
      if (!r.add_schema(text, d)) throw std::runtime_error(d.to_string());
    return r;
  }();
  return registry;
}

std::span<const uint32_t> test_shader(const std::string& name) {
  return find_shader(gpu_test_shaders(), "tests/runtime/shaders/" + name);
}

float param(const PlanNode& node, std::string_view name) {
  const JsonValue* v = node.params.find(name);
  return v ? static_cast<float>(v->as_number()) : 0.0f;
}

bool sampled(const Plan& plan, const PlanPass& pass, std::string_view slot) {
  return std::ranges::any_of(plan.accesses_of(pass),
                             [&](const PlanAccess& a) { return plan.slot_of(a) == slot && a.usage == Usage::sampled; });
}

class TestKernel final : public NodeKernel {
 public:
  TestKernel(std::vector<TestStep> steps, std::shared_ptr<std::map<std::string, int>> calls)
      : steps_(std::move(steps)), calls_(std::move(calls)) {}

  void record(PassContext& pc) override {
    ++(*calls_)[pc.node().type];
    auto step = std::find_if(steps_.begin(), steps_.end(), [&](const TestStep& s) { return s.pass == pc.pass().pass; });
    if (step == steps_.end()) throw std::runtime_error("no step for pass " + pc.pass().pass);
    if (pc.plan().resources[resource_of(pc, step->target)].desc.kind == ResourceKind::buffer)
      return fill_buffer(pc, *step);
    Image& target = pc.image(step->target);
    std::vector<DescriptorWrite> writes;
    std::string shader = "exec_fill.comp";
    float constant = param(pc.node(), "value");
    if (!step->source.empty()) {
      Image& source = pc.image(step->source);
      const bool through_sampler = sampled(pc.plan(), pc.pass(), step->source);
      shader = through_sampler ? "exec_add_sampled.comp" : "exec_add_storage.comp";
      writes.push_back(through_sampler ? sampled_image(0, source.view(), pc.nearest_sampler())
                                       : storage_image(0, source.view()));
      constant = pc.node().params.find("add") ? param(pc.node(), "add") : step->add;
    }
    writes.push_back(storage_image(static_cast<uint32_t>(writes.size()), target.view()));
    std::vector<DescriptorBinding> bindings;
    for (const DescriptorWrite& w : writes) bindings.push_back({w.binding, w.type});
    const Pipeline& p = pc.pipelines().compute({shader, test_shader(shader), bindings, sizeof(float)});
    bind_pipeline(pc.gpu(), pc.cmd(), p, writes);
    push_constants(pc.cmd(), p, constant);
    vkCmdDispatch(pc.cmd(), (target.desc().width + 7) / 8, (target.desc().height + 7) / 8, 1);
  }

 private:
  static int resource_of(PassContext& pc, const std::string& slot) {
    for (const PlanAccess& a : pc.plan().accesses_of(pc.pass()))
      if (pc.plan().slot_of(a) == slot) return a.resource;
    pc.image(slot);  // throws naming the slot
    return -1;
  }

  void fill_buffer(PassContext& pc, const TestStep& step) {
    Buffer& target = pc.buffer(step.target);
    const DescriptorWrite writes[] = {storage_buffer(0, target.handle())};
    const Pipeline& p = pc.pipelines().compute(
        {"exec_buffer.comp", test_shader("exec_buffer.comp"), {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}, sizeof(float)});
    bind_pipeline(pc.gpu(), pc.cmd(), p, writes);
    push_constants(pc.cmd(), p, param(pc.node(), "value"));
    vkCmdDispatch(pc.cmd(), static_cast<uint32_t>((target.size() / 16 + 63) / 64), 1, 1);
  }

  std::vector<TestStep> steps_;
  std::shared_ptr<std::map<std::string, int>> calls_;
};

// Draws mesh 0 of the GpuScene with its index buffer into a cleared colour attachment.
class RasterKernel final : public NodeKernel {
 public:
  void record(PassContext& pc) override {
    Image& target = pc.image("out.color");
    const GpuMesh& mesh = pc.gpu_scene().mesh(0);
    GraphicsPipelineDesc desc;
    desc.name = "exec_mesh";
    desc.vertex_shader = test_shader("exec_mesh.vert");
    desc.fragment_shader = test_shader("exec_mesh.frag");
    use_gpu_vertices(desc);
    desc.color_formats = {target.desc().format};
    const Pipeline& p = pc.pipelines().graphics(desc);
    VkRenderingAttachmentInfo color = cleared_attachment(target.view());
    const uint32_t w = target.desc().width, h = target.desc().height;
    const VkRenderingInfo rendering = rendering_info(w, h, {&color, 1});
    VkCommandBuffer cmd = pc.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    bind_pipeline(pc.gpu(), cmd, p);
    set_viewport(cmd, w, h);
    draw_mesh(cmd, mesh);
    vkCmdEndRendering(cmd);
  }
};

class ThrowingKernel final : public NodeKernel {
 public:
  void record(PassContext&) override { throw std::runtime_error("the shader is missing"); }
};

}  // namespace

TestKernels test_kernels() {
  TestKernels k;
  auto add = [&](std::string type, std::vector<TestStep> steps) {
    k.registry.add(std::move(type),
                   [steps, calls = k.calls](const PlanNode&) { return std::make_unique<TestKernel>(steps, calls); });
  };
  add("test.fill", {{"fill", "", "out.color"}});
  add("test.bake", {{"fill", "", "out.color"}});
  add("test.add", {{"add", "in.src", "out.color", 1}});
  add("test.accumulate", {{"accumulate", "in.history", "out.color", 1}});
  add("test.two_pass", {{"first", "in.src", "tmp.tmp", 1}, {"second", "tmp.tmp", "out.color", 1}});
  add("test.sh", {{"write", "", "out.sh"}});
  add("test.lit", {{"direct", "", "out.color"}});  // "area" has no step: running it throws
  k.registry.add("test.raster", [](const PlanNode&) { return std::make_unique<RasterKernel>(); });
  k.registry.add("test.boom", [](const PlanNode&) { return std::make_unique<ThrowingKernel>(); });
  return k;
}

Plan compile_test_graph(const Context& context, std::string_view graph_json, bool alias, FrameSize frame,
                        const SceneSummary& scene) {
  Diagnostics d("test graph");
  std::optional<Graph> graph = parse_graph_text(graph_json, d);
  if (!graph) throw std::runtime_error(d.to_string());
  CompileOptions options;
  options.scene = scene;
  options.frame = frame;
  options.alias = device_alias_options(context);
  options.alias.enabled = alias;
  CompileResult result = compile(*graph, test_registry(), options, d);
  if (!result.plan) throw std::runtime_error(d.to_string());
  return std::move(*result.plan);
}

}  // namespace lg::test
