// A game loop in miniature, built against the installed lumagraph package: load a graph file
// and a world, render frames into the graph's output, read the last one back and check it.
//
//   lumagraph-consumer GRAPH [WORLD] [--size WxH] [--frames N] [--validate] [--out FILE.png]
//
// Without WORLD it renders the embedded default world. Exit status 0: every frame rendered,
// every pixel finite and, with --validate, no validation message; 1 otherwise; 2 for bad usage.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "api/renderer.h"
#include "api/world_loading.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/default_world.h"

namespace {

struct Options {
  std::string graph, world, out;
  lg::FrameSize size{320, 180};
  int frames = 3;
  bool validate = false;
};

bool parse_size(std::string_view text, lg::FrameSize& size) {
  const size_t x = text.find('x');
  if (x == std::string_view::npos) return false;
  const auto w = std::from_chars(text.data(), text.data() + x, size.width);
  const auto h = std::from_chars(text.data() + x + 1, text.data() + text.size(), size.height);
  return w.ec == std::errc{} && h.ec == std::errc{} && h.ptr == text.data() + text.size() && size.width > 0 &&
         size.height > 0;
}

bool parse(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--validate") {
      options.validate = true;
    } else if (arg == "--size" && has_value) {
      if (!parse_size(argv[++i], options.size)) return false;
    } else if (arg == "--frames" && has_value) {
      const std::string_view text = argv[++i];
      const auto n = std::from_chars(text.data(), text.data() + text.size(), options.frames);
      if (n.ec != std::errc{} || n.ptr != text.data() + text.size() || options.frames < 1) return false;
    } else if (arg == "--out" && has_value) {
      options.out = argv[++i];
    } else if (arg.starts_with("--")) {
      return false;
    } else if (options.graph.empty()) {
      options.graph = arg;
    } else if (options.world.empty()) {
      options.world = arg;
    } else {
      return false;
    }
  }
  return !options.graph.empty();
}

// Validation messages since the last call, printed; how many.
size_t report_validation(lg::Context& context) {
  const auto messages = context.take_validation_messages();
  for (const auto& m : messages) std::fprintf(stderr, "validation: [%s] %s\n", m.id.c_str(), m.text.c_str());
  return messages.size();
}

int run(const Options& options) {
  lg::RendererOptions renderer_options;
  renderer_options.device.validation = options.validate;
  renderer_options.device.application_name = "lumagraph-consumer";
  lg::Renderer renderer(renderer_options);
  renderer.load_graph(options.graph);
  const lg::World world = options.world.empty()
                              ? lg::default_world()
                              : lg::load_world(options.world, lg::renderer_world_options(options.world));

  size_t validation_messages = 0;
  for (int frame = 0; frame < options.frames; ++frame) {
    const lg::FrameStats& stats = renderer.render(world, options.size);
    std::printf("frame %d: %zu passes, %.1f ms on the GPU\n", frame, stats.passes.size(), stats.gpu_ms);
    validation_messages += report_validation(renderer.context());
  }

  const std::vector<float> rgba = renderer.read_output();
  double sum[3] = {0, 0, 0};
  size_t non_finite = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(rgba[i + c]))
        ++non_finite;
      else
        sum[c] += rgba[i + c];
    }
  }
  const double pixels = double(rgba.size() / 4);
  std::printf("output %ux%u: mean rgb %.4f %.4f %.4f, %zu non-finite values\n", options.size.width, options.size.height,
              sum[0] / pixels, sum[1] / pixels, sum[2] / pixels, non_finite);
  if (!options.out.empty()) lg::save_image(options.out, options.size.width, options.size.height, rgba);
  if (validation_messages > 0) std::fprintf(stderr, "%zu validation messages\n", validation_messages);
  return non_finite == 0 && validation_messages == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parse(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: lumagraph-consumer GRAPH [WORLD] [--size WxH] [--frames N] [--validate] [--out FILE.png]\n");
    return 2;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph-consumer: %s\n", e.what());
    return 1;
  }
}
