// gi.reflection_capture on lavapipe: examples/reflection-probes.json on
// examples/worlds/reflection-room.json (a chrome ball on a steel floor in a closed room) against
// the path tracer's specular AOV, with lighting.ibl's specular from the environment only, from the
// probe without parallax correction and from the probe with it; and the coverage inside and outside a probe's
// influence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/gi/path_tracer/path_tracer.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{160, 96};
constexpr const char* kExample = "examples/reflection-probes.json";
constexpr const char* kProbeLink = R"({ "from": "probes.reflections", "to": "ibl.reflection_probes" },)";
constexpr const char* kProbeParams = R"("params": { "capture": "raster", "face_size": 128, "second_bounce": true })";

enum class Specular { environment, probes_without_parallax, probes };
enum class Capture { path_traced, raster, raster_two_bounces };

// The example graph with small captures (32x32 faces; path traced at 8 paths a texel: enough for
// a room of smooth colours, and cheap), its probe linked into lighting.ibl or not, parallax on or off.
Graph probe_graph(Specular mode, Capture capture = Capture::path_traced) {
  std::ifstream file(std::filesystem::path(LUMAGRAPH_SOURCE_DIR) / kExample);
  std::stringstream text;
  text << file.rdbuf();
  std::string graph = text.str();
  const size_t link = graph.find(kProbeLink), params = graph.find(kProbeParams);
  if (link == std::string::npos || params == std::string::npos)
    throw std::runtime_error(std::string(kExample) + " no longer has the probe link or params this test edits");
  // The link comes after the params: erased first, it leaves their offset as it is.
  if (mode == Specular::environment) graph.erase(link, std::string(kProbeLink).size());
  const char* capture_params[] = {R"("capture": "path_traced", "face_size": 32, "samples": 8, "bounces": 3)",
                                  R"("capture": "raster", "face_size": 32)",
                                  R"("capture": "raster", "face_size": 32, "second_bounce": true)"};
  graph.replace(params, std::string(kProbeParams).size(),
                std::string(R"("params": { )") + capture_params[int(capture)] + R"(, "parallax": )" +
                    (mode == Specular::probes ? "true" : "false") + " }");
  Diagnostics d(kExample);
  std::optional<Graph> g = parse_graph_text(graph, d);
  if (!g) throw std::runtime_error(d.to_string());
  return std::move(*g);
}

struct Frame {
  std::vector<float> direct, lit, material;  // light.color, ibl.color, the G-buffer's material (RGBA)
  PathEnvironment environment;
};

// One renderer for every variant of the graph: it makes each pipeline once; a new graph gets a new
// executor, so nothing of the last variant's frame but its static results (kept only where their
// keys hold) carries over.
Renderer make_renderer() {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // intermediate results are read back after the frame
  return Renderer(options);
}

Frame render(Renderer& renderer, const World& world, Specular mode, Capture capture = Capture::path_traced) {
  renderer.set_graph(probe_graph(mode, capture));
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  return {renderer.executor().read_image("light.color"), renderer.executor().read_image("ibl.color"),
          renderer.executor().read_image("gbuf.gbuffer.material"),
          plan_environment(renderer.plan(), renderer.scene_view().has_environment, "reflection probe test")};
}

// The ball and the floor are metal (no diffuse part), so lighting.ibl's light on them, its colour
// less the direct light, is their specular term alone: what the reference's specular AOV holds.
// Over the metal pixels, the mean absolute difference per channel relative to the reference's
// mean there, for each source of the specular light.
TEST(ReflectionProbes, ParallaxCorrectedProbeIsCloserToTheReferenceThanTheEnvironment) {
  const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/reflection-room.json");
  Renderer renderer = make_renderer();
  const Frame environment = render(renderer, world, Specular::environment);
  const Frame flat = render(renderer, world, Specular::probes_without_parallax);
  const Frame parallax = render(renderer, world, Specular::probes);
  const Frame raster_flat = render(renderer, world, Specular::probes_without_parallax, Capture::raster);
  const Frame raster = render(renderer, world, Specular::probes, Capture::raster);
  const Frame two_flat = render(renderer, world, Specular::probes_without_parallax, Capture::raster_two_bounces);
  const Frame two = render(renderer, world, Specular::probes, Capture::raster_two_bounces);
  const PathScene scene(make_scene_view(world, float(kFrame.width) / kFrame.height), parallax.environment);
  PathTracerOptions o;
  o.width = kFrame.width, o.height = kFrame.height, o.samples_per_pixel = 64;
  const ReferenceImage traced = trace_reference(scene, o);
  const auto& mean = traced.mean_of(ReferenceAov::specular);
  const auto& error = traced.error_of(ReferenceAov::specular);
  constexpr int kFrames = 7;
  double reference = 0.0, noise = 0.0, errors[kFrames] = {};
  const Frame* frames[kFrames] = {&environment, &flat, &parallax, &raster_flat, &raster, &two_flat, &two};
  size_t pixels = 0;
  for (size_t i = 0; i < traced.pixel_count(); ++i) {
    if (!(parallax.material[4 * i + 1] > 0.5f)) continue;  // metalness
    ++pixels;
    for (int c = 0; c < 3; ++c) {
      const double truth = mean[i][c];
      reference += truth;
      noise += error[i][c];
      for (int f = 0; f < kFrames; ++f)
        errors[f] += std::abs(frames[f]->lit[4 * i + c] - frames[f]->direct[4 * i + c] - truth);
    }
  }
  std::printf(
      "%zu metal pixels of %zu: mean |error| / mean reference: environment only %.4f; path-traced capture: probe "
      "without parallax %.4f, with parallax %.4f; raster capture: without parallax %.4f, with %.4f; raster, second "
      "bounce: without parallax %.4f, with %.4f (reference noise %.4f)\n",
      pixels, traced.pixel_count(), errors[0] / reference, errors[1] / reference, errors[2] / reference,
      errors[3] / reference, errors[4] / reference, errors[5] / reference, errors[6] / reference, noise / reference);
  ASSERT_GT(pixels, traced.pixel_count() / 4);  // the floor and the ball fill much of the view
  // Measured (the ball "captured_by_probes": false): environment only 3.75 of the reference's mean
  // (it mirrors the sky in a closed room), the probe without parallax 0.81, with parallax 0.59;
  // the reference's own noise (its
  // mean standard error at 64 paths, 0.33) is in all three. Required: the corrected probe at most
  // half the environment's error, and below 0.9 of the uncorrected probe's (both cases use the
  // same capture, so the difference is the correction's alone). Without the probe linked the
  // first two errors are equal, without the correction the last two: either way the test fails.
  EXPECT_LT(errors[2], 0.5 * errors[0]);
  EXPECT_LT(errors[2], 0.9 * errors[1]);
  // The raster capture, lit by the room's irradiance volume (the example links it; measured: 0.79
  // and 0.80 without and with parallax, 0.73 and 0.57 with the second bounce; before the room had
  // a volume its walls held the sky's SH through the closed walls and no light between them: 1.27,
  // 1.30, 1.21, 1.06). Required: its corrected probe with the second bounce at most half the
  // environment's error, closer than the first bounce alone (which mirrors the sky in the cube's
  // steel floor), and below 0.9 of its uncorrected lookup (0.78 measured; the same capture, so the
  // difference is the correction's).
  EXPECT_LT(errors[6], 0.5 * errors[0]);
  EXPECT_LT(errors[6], errors[4]);
  EXPECT_LT(errors[6], 0.9 * errors[5]);
}

// The capture node alone on the reflection room, its probe's influence moved to the room's left
// half (entity at x = -1, box half sizes 1.2 across: x from -2.2 to 0.2, blend 0.1 m) with the
// room as proxy through its offset: the red wall (x = -2, 0.2 m inside) has coverage 1, the green
// wall (x = 2, outside) 0, where lighting.ibl keeps the environment; every texel finite.
TEST(ReflectionProbes, CoverageIsOneInsideTheInfluenceAndZeroOutside) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/reflection-room.json");
  Entity probe;
  world.each<ReflectionProbe>([&](Entity e, const ReflectionProbe&) { probe = e; });
  ASSERT_FALSE(probe.is_null());
  world.get<Transform>(probe).position = {-1.0f, 1.5f, 0.0f};
  ReflectionProbe& p = world.get<ReflectionProbe>(probe);
  p.extent = {1.2f, 1.6f, 2.1f};
  p.proxy_extent = {2.0f, 1.5f, 2.0f};
  p.proxy_offset = {1.0f, 0.0f, 0.0f};
  Diagnostics d("coverage-test.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "probes", "type": "gi.reflection_capture", "params": { "capture": "path_traced", "face_size": 8, "samples": 1, "bounces": 1 } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "probes.gbuffer" } ],
    "outputs": [ "probes.reflections" ] })",
                                                d);
  ASSERT_TRUE(graph) << d.to_string();
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the G-buffer is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(std::move(*graph));
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  const std::vector<float> reflections = renderer.executor().read_image("probes.reflections");
  const std::vector<float> albedo = renderer.executor().read_image("gbuf.gbuffer.albedo");
  size_t red = 0, green = 0;
  for (size_t i = 0; i < reflections.size(); i += 4) {
    for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(reflections[i + c])) << "texel " << i / 4;
    // The walls' base colours, red (0.7, 0.08, 0.05) and green (0.12, 0.5, 0.1), told apart from
    // the others (blue, white, steel) whether read back linear or sRGB-encoded.
    const float r = albedo[i], g = albedo[i + 1], b = albedo[i + 2];
    if (r > 2.0f * g && r > 2.0f * b) {
      ++red;
      EXPECT_FLOAT_EQ(reflections[i + 3], 1.0f) << "red wall texel " << i / 4;
    } else if (g > 1.5f * r && g > 1.5f * b) {
      ++green;
      EXPECT_FLOAT_EQ(reflections[i + 3], 0.0f) << "green wall texel " << i / 4;
    }
  }
  EXPECT_GT(red, 500u);  // both walls fill a good part of the 160x96 view
  EXPECT_GT(green, 500u);
}

size_t captures_in(const std::string& log) {
  size_t count = 0;
  for (size_t at = log.find("captured"); at != std::string::npos; at = log.find("captured", at + 1)) ++count;
  return count;
}

// The cubes are static: a second frame of the same scene keeps them (even with the camera moved),
// a moved probe captures again. Fails if the capture ran every frame or ignored the probes.
TEST(ReflectionProbes, CaptureIsCachedUntilTheProbesChange) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/reflection-room.json");
  Graph graph = probe_graph(Specular::probes);
  RendererOptions options;
  options.device.validation = true;
  Renderer renderer(options);
  renderer.set_graph(std::move(graph));
  Entity probe, camera;
  world.each<ReflectionProbe>([&](Entity e, const ReflectionProbe&) { probe = e; });
  world.each<Camera>([&](Entity e, const Camera&) { camera = e; });
  testing::internal::CaptureStderr();
  renderer.render(world, kFrame);
  world.get<Transform>(camera).position.x += 0.2f;
  renderer.render(world, kFrame);
  const size_t unchanged = captures_in(testing::internal::GetCapturedStderr());
  testing::internal::CaptureStderr();
  world.get<Transform>(probe).position.y += 0.1f;
  renderer.render(world, kFrame);
  const size_t moved = captures_in(testing::internal::GetCapturedStderr());
  EXPECT_EQ(unchanged, 1u);
  EXPECT_EQ(moved, 1u);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
}

}  // namespace
}  // namespace lg::test
