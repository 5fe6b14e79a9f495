#include "tests/post/exposure_harness.h"

#include <stdexcept>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_kernels.h"
#include "nodes/builtin_schemas.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/plan_resources.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/image/image_file.h"

namespace lg::test {
namespace {

constexpr std::string_view kImageSchema = R"({ "type": "test.image", "doc": "The test's image, copied in every frame.",
  "params": [ { "name": "scale", "type": "float", "default": 1, "min": 0.25, "max": 1, "doc": "Its size over the frame's." } ],
  "outputs": [ { "name": "color", "type": "texture2d:hdr", "extent": "frame", "scale": "param:scale", "doc": "The image." } ],
  "passes": [ { "name": "copy", "queue": "compute", "uses": { "out.color": "storage_write" } } ] })";

// Copies the host image through a staging buffer into its output, which the plan leaves in
// GENERAL for the storage write the schema declares: the barriers around the copy move it to
// the transfer's layout and back, waiting for everything (the plan's expect a shader write).
class ImageKernel final : public NodeKernel {
 public:
  explicit ImageKernel(std::shared_ptr<HostImage> image) : image_(std::move(image)) {}

  void record(PassContext& ctx) override {
    Image& out = ctx.image("out.color");
    if (out.desc().width != image_->width || out.desc().height != image_->height ||
        image_->rgba.size() != size_t{image_->width} * image_->height * 4)
      throw std::invalid_argument("test.image: the image does not match the frame's size");
    const FormatInfo& format = format_info(out.desc().format);
    const uint64_t bytes = uint64_t{image_->width} * image_->height * format.bytes_per_texel;
    if (staging_.size() != bytes)
      staging_ = Buffer::dedicated(ctx.gpu(), {.name = "test.image staging", .size = bytes}, MemoryUse::upload);
    encode_texels(format, image_->rgba, {staging_.mapped(), bytes});  // frames run one at a time
    image_barrier(ctx.cmd(), out, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image_->width, image_->height, 1};
    vkCmdCopyBufferToImage(ctx.cmd(), staging_.handle(), out.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region);
    image_barrier(ctx.cmd(), out, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
  }

 private:
  std::shared_ptr<HostImage> image_;
  Buffer staging_;
};

const Registry& registry_with_image() {
  static const Registry registry = [] {
    Registry r;
    Diagnostics d("schemas");
    for (const EmbeddedFile& f : embedded_node_schemas()) r.add_schema(f.text, d);
    if (!r.add_schema(kImageSchema, d)) throw std::logic_error(d.to_string());
    return r;
  }();
  return registry;
}

Plan compile_graph(const Context& context, std::string_view graph_json, FrameSize frame, const SceneSummary& scene) {
  Diagnostics d("exposure test graph");
  std::optional<Graph> graph = parse_graph_text(graph_json, d);
  if (!graph) throw std::invalid_argument(d.to_string());
  CompileOptions options;
  options.scene = scene;
  options.frame = frame;
  options.alias = device_alias_options(context);
  options.alias.enabled = false;
  CompileResult result = compile(*graph, registry_with_image(), options, d);
  if (!result.plan) throw std::invalid_argument(d.to_string());
  return std::move(*result.plan);
}

}  // namespace

ExposureHarness::ExposureHarness(Context& context, std::string_view graph_json, HostImage image,
                                 std::optional<FrameSize> frame, const SceneSummary& scene)
    : image_(std::make_shared<HostImage>(std::move(image))), kernels_(builtin_kernels()), gpu_scene_(context) {
  kernels_.add("test.image", [image = image_](const PlanNode&) { return std::make_unique<ImageKernel>(image); });
  executor_ = std::make_unique<Executor>(
      context, kernels_,
      compile_graph(context, graph_json, frame.value_or(FrameSize{image_->width, image_->height}), scene));
}

FrameStats ExposureHarness::run_frame() {
  return executor_->run_frame(scene_, gpu_scene_);
}

float ExposureHarness::read_scalar(std::string_view resource) {
  return executor_->read_image(resource).at(0);
}

std::string exposure_graph(std::string_view params, bool history) {
  std::string g = R"({ "format": "lumagraph/1", "nodes": [ { "id": "src", "type": "test.image" },
    { "id": "exposure", "type": "post.exposure", "params": )" +
                  std::string(params) + R"( } ],
    "links": [ { "from": "src.color", "to": "exposure.color" })";
  if (history) g += R"(, { "from": "exposure.exposure", "to": "exposure.history" })";
  return g + R"( ], "outputs": [ "exposure.exposure", "src.color" ] })";
}

HostImage load_host_image(const std::string& path) {
  ImageData data = load_image(path);
  return {data.width, data.height, std::move(data.rgba)};
}

}  // namespace lg::test
