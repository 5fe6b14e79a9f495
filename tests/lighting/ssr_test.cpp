// lighting.ssr on lavapipe: examples/ssr.json on examples/worlds/ssr-floor.json (a polished steel
// floor under coloured boxes) against the path tracer's specular AOV, with and without the
// reflections linked into lighting.ibl and at half resolution; and degenerate input (sky, grazing
// rays, depth at the near plane, a NaN and Inf lit image) that must leave every output finite, at
// full resolution and at a third of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/gi/path_tracer/path_tracer.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "runtime/gpu/transfer.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{160, 96};
constexpr const char* kSsrLink = R"({ "from": "ssr.reflections", "to": "ibl.ssr" },)";

// examples/ssr.json, with the reflections linked into lighting.ibl or not (the environment only),
// traced at `scale` of the G-buffer's resolution; at scale 0 with the node's default quality
// (resolution_scale and max_steps left to the schema).
Graph ssr_graph(bool linked, double scale = 1.0) {
  std::ifstream file(LUMAGRAPH_SOURCE_DIR "/examples/ssr.json");
  std::stringstream text;
  text << file.rdbuf();
  std::string graph = text.str();
  const size_t link = graph.find(kSsrLink);
  if (link == std::string::npos) throw std::runtime_error("examples/ssr.json no longer links ssr into ibl");
  if (!linked) graph.erase(link, std::string(kSsrLink).size());
  Diagnostics d("examples/ssr.json");
  std::optional<Graph> g = parse_graph_text(graph, d);
  if (!g) throw std::runtime_error(d.to_string());
  for (GraphNode& node : g->nodes) {
    if (node.type != "lighting.ssr") continue;
    if (scale > 0) {
      node.params.set("resolution_scale", scale);
    } else {
      std::erase_if(node.params.members(),
                    [](const JsonValue::Member& m) { return m.first == "resolution_scale" || m.first == "max_steps"; });
    }
  }
  return std::move(*g);
}

struct Frame {
  std::vector<float> direct, lit, reflections;  // light.color, ibl.color, ssr.reflections (RGBA)
  PathEnvironment environment;
};

// `frames` frames (from the second on, the reflections read the last frame's lit image).
Frame render(const World& world, bool linked, int frames, double scale = 1.0) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // intermediate results are read back after the frame
  Renderer renderer(options);
  renderer.set_graph(ssr_graph(linked, scale));
  for (int f = 0; f < frames; ++f) renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  Frame out{renderer.executor().read_image("light.color"),
            renderer.executor().read_image("ibl.color"),
            {},
            plan_environment(renderer.plan(), renderer.scene_view().has_environment, "ssr test")};
  if (linked) out.reflections = renderer.executor().read_image("ssr.reflections");
  return out;
}

// The floor is metal (no diffuse part), so lighting.ibl's light on it, its colour less the direct
// light, is its specular term alone: what the reference's specular AOV holds. Compared over the
// pixels where `mask`'s reflections are confident (more than half), as a mean absolute difference
// per channel relative to the reference's mean there.
struct FloorErrors {
  size_t pixels = 0;
  double ssr = 0, environment = 0, noise = 0;  // relative to the reference's mean
};

FloorErrors floor_errors(const ReferenceImage& traced, const Frame& mask, const Frame& with, const Frame& without) {
  const auto& mean = traced.mean_of(ReferenceAov::specular);
  const auto& error = traced.error_of(ReferenceAov::specular);
  double reference = 0.0;
  FloorErrors out;
  for (size_t i = 0; i < traced.pixel_count(); ++i) {
    if (!(mask.reflections[4 * i + 3] > 0.5f)) continue;
    ++out.pixels;
    for (int c = 0; c < 3; ++c) {
      const double truth = mean[i][c];
      reference += truth;
      out.ssr += std::abs(with.lit[4 * i + c] - with.direct[4 * i + c] - truth);
      out.environment += std::abs(without.lit[4 * i + c] - without.direct[4 * i + c] - truth);
      out.noise += error[i][c];
    }
  }
  out.ssr /= reference, out.environment /= reference, out.noise /= reference;
  std::printf(
      "%zu confident pixels of %zu: mean |error| / mean reference: ssr %.4f, environment only %.4f "
      "(reference noise %.4f)\n",
      out.pixels, traced.pixel_count(), out.ssr, out.environment, out.noise);
  return out;
}

ReferenceImage floor_reference(const World& world, const PathEnvironment& environment) {
  const PathScene scene(make_scene_view(world, float(kFrame.width) / kFrame.height), environment);
  PathTracerOptions o;
  o.width = kFrame.width, o.height = kFrame.height, o.samples_per_pixel = 128;
  return trace_reference(scene, o);
}

TEST(ScreenSpaceReflections, ConfidentPixelsAreCloserToTheReferenceThanTheEnvironment) {
  const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/ssr-floor.json");
  const Frame with = render(world, true, 3);
  const Frame without = render(world, false, 1);
  const ReferenceImage traced = floor_reference(world, with.environment);
  const FloorErrors e = floor_errors(traced, with, with, without);
  ASSERT_GT(e.pixels, traced.pixel_count() / 20);  // the floor's reflections of the boxes (9.7%)
  // Measured: ssr 0.47, environment only 1.08 of the reference's mean, with its own noise (the
  // mean standard error at 128 paths, 0.13) in both. Required: at most 75% of the environment's
  // error, well clear of that noise; with lighting.ibl ignoring the reflections the two are equal
  // (1.082 and 1.083: the test fails).
  EXPECT_LT(e.ssr, 0.75 * e.environment);
}

// resolution_scale 0.5: rays for a quarter of the pixels, resolved on that grid and upsampled
// guided by depth and normals. Over the pixels where the full-resolution reflections are
// confident, the floor's error may grow by at most a fifth of the full-resolution error: the
// boxes' reflected edges are where the coarser grid loses detail, and a fifth is what those edges
// (a few per cent of the pixels, each off by the contrast between a box and the sky) can add.
// The node's default quality (resolution_scale 0.25, 48 steps: chosen for the issue's 60 ms at
// 1280x720 on lavapipe, which is not yet shown on a quiet machine) is held to the same bound: measured 0.451 against 0.414 at full
// resolution and 64 steps (1.09x; 0.5 gives 0.429, 1/3 0.440).
TEST(ScreenSpaceReflections, CoarserGridsKeepTheAccuracy) {
  const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/ssr-floor.json");
  const Frame full = render(world, true, 3);
  const Frame half = render(world, true, 3, 0.5);
  const Frame fast = render(world, true, 3, 0.0);
  const Frame without = render(world, false, 1);
  const ReferenceImage traced = floor_reference(world, full.environment);
  const FloorErrors at_full = floor_errors(traced, full, full, without);
  const FloorErrors at_half = floor_errors(traced, full, half, without);
  const FloorErrors at_default = floor_errors(traced, full, fast, without);
  ASSERT_GT(at_full.pixels, traced.pixel_count() / 20);
  EXPECT_LT(at_half.ssr, 1.2 * at_full.ssr);
  EXPECT_LT(at_default.ssr, 1.2 * at_full.ssr);
}

// The first frame's hits reflect `color` alone (the direct light: no lit image exists yet), so the
// second frame must not blend that result in: its reflections equal, bit for bit, those of the same
// frames without temporal accumulation; the third frame blends the second's (they differ). Fails
// when the first frame is carried: at temporal_blend 0.9 it was still 48% of the reflections
// after 8 frames, which left the gallery floor's reflections too dark (docs/reflection-probes.md).
TEST(ScreenSpaceReflections, FirstFrameHitsOfDirectLightAreNotAccumulated) {
  const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/ssr-floor.json");
  const auto reflections = [&](double temporal_blend) {
    Graph graph = ssr_graph(true);
    for (GraphNode& node : graph.nodes)
      if (node.type == "lighting.ssr") node.params.set("temporal_blend", temporal_blend);
    RendererOptions options;
    options.device.validation = true;
    options.alias = false;
    Renderer renderer(options);
    renderer.set_graph(graph);
    std::vector<std::vector<float>> frames;
    for (int f = 0; f < 3; ++f) {
      renderer.render(world, kFrame);
      frames.push_back(renderer.executor().read_image("ssr.reflections"));
    }
    auto messages = renderer.context().take_validation_messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
    return frames;
  };
  const auto accumulated = reflections(0.9), alone = reflections(0.0);
  size_t confident = 0;
  for (size_t i = 3; i < alone[1].size(); i += 4) confident += alone[1][i] > 0.5f;
  ASSERT_GT(confident, alone[1].size() / 4 / 20);  // the floor reflects the boxes
  EXPECT_EQ(accumulated[1], alone[1]);
  EXPECT_NE(accumulated[2], alone[2]);
}

// Degenerate input: a mirror floor (roughness 0) seen at a grazing angle from 2 cm above it, the
// sky above the horizon (depth 0), a rough metal box, and a box face just beyond the near plane
// (depth near 1); after the first frame the lit image the reflections read is overwritten with
// NaN and Inf texels. Every output texel stays finite and confidences stay in [0, 1].
World grazing_world() {
  World world;
  PbrMaterial mirror;
  mirror.roughness = 0.0f, mirror.metalness = 1.0f;
  PbrMaterial rough;
  rough.roughness = 1.0f, rough.metalness = 1.0f;
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(40.0f, 40.0f)), world.add_material(mirror)});
  world.add(floor, Transform{});
  Entity box = world.create("box");
  world.add(box, MeshRenderer{world.add_mesh(make_box({1.0f, 1.0f, 1.0f})), world.add_material(rough)});
  world.add(box, Transform{}).position = {0.5f, 0.5f, -4.0f};
  Entity close = world.create("close");  // its face 0.0501 m in front of the camera, in one corner
  world.add(close, MeshRenderer{world.add_mesh(make_box({0.1f, 0.1f, 0.1f})), world.add_material(mirror)});
  world.add(close, Transform{}).position = {0.075f, 0.02f, -0.1001f};
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  Transform& view = world.add(camera, Transform{});
  view.position = {0.0f, 0.02f, 0.0f};
  view.rotation = look_rotation({0.0f, 0.05f, -1.0f});
  Entity sky = world.create("sky");
  world.add(sky, EnvironmentLight{});
  Entity sun = world.create("sun");
  world.add(sun, DirectionalLight{.intensity = 3.0f});
  world.add(sun, Transform{}).rotation = look_rotation({0.3f, -1.0f, -0.4f});
  return world;
}

size_t non_finite(const std::vector<float>& texels) {
  size_t bad = 0;
  for (float v : texels) bad += !std::isfinite(v);
  return bad;
}

void expect_finite_on_degenerate_input(double scale) {
  const World world = grazing_world();
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;
  Renderer renderer(options);
  renderer.set_graph(ssr_graph(true, scale));
  renderer.render(world, kFrame);
  // The next frame's history: NaN and Inf in every other texel's channels.
  Image& lit = renderer.executor().image("ibl.color");
  std::vector<float> broken(size_t{kFrame.width} * kFrame.height * 4, 1.0f);
  for (size_t i = 0; i < broken.size(); i += 8) {
    broken[i] = std::numeric_limits<float>::quiet_NaN();
    broken[i + 1] = std::numeric_limits<float>::infinity();
  }
  const VkImageLayout layout = renderer.executor().layout("ibl.color");
  upload_image(renderer.executor().submitter(), lit, broken, layout, {}, layout);
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  const std::vector<float> reflections = renderer.executor().read_image("ssr.reflections");
  EXPECT_EQ(non_finite(reflections), 0u);
  EXPECT_EQ(non_finite(renderer.executor().read_image("ibl.color")), 0u);
  size_t confident = 0;
  float brightest = 0.0f;
  for (size_t i = 0; i < reflections.size(); i += 4) {
    EXPECT_GE(reflections[i + 3], 0.0f);
    EXPECT_LE(reflections[i + 3], 1.0f);
    confident += reflections[i + 3] > 0.0f;
    brightest = std::max({brightest, reflections[i], reflections[i + 1], reflections[i + 2]});
  }
  EXPECT_GT(confident, 0u);  // the grazing floor reflects the boxes: rays were traced
  // A broken texel reflects as 0: the lit scene is below 100 here, while NaN or Inf let through
  // come out of lavapipe's min() as the half-float maximum (65504).
  EXPECT_LT(brightest, 100.0f);
}

TEST(ScreenSpaceReflections, DegenerateInputLeavesEveryOutputFinite) {
  expect_finite_on_degenerate_input(1.0);
}

// A third of the resolution: the 160-pixel rows make a grid of 54 texels, the last one standing
// for the 1 pixel left over, which the upsample's last block must cover.
TEST(ScreenSpaceReflections, DegenerateInputAtAThirdOfTheResolutionLeavesEveryOutputFinite) {
  expect_finite_on_degenerate_input(1.0 / 3.0);
}

}  // namespace
}  // namespace lg::test
