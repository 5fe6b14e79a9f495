// gi.reflection_capture's raster capture on lavapipe: its cube faces against the path-traced
// capture of the same probe where the two hold the same light, and the time-sliced capture
// (faces_per_frame) against the whole capture after one round of faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/gi/reflection_capture/captured_cube_source.h"
#include "runtime/scene/load_world.h"
#include "tests/gi/plan_kernel.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{160, 96};
constexpr const char* kRoom = LUMAGRAPH_SOURCE_DIR "/examples/worlds/reflection-room.json";

std::string read_example() {
  std::ifstream file(LUMAGRAPH_SOURCE_DIR "/examples/reflection-probes.json");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

Graph parse(const std::string& text) {
  Diagnostics d("raster-capture-test.json");
  std::optional<Graph> g = parse_graph_text(text, d);
  if (!g) throw std::runtime_error(d.to_string());
  return std::move(*g);
}

std::unique_ptr<Renderer> make_renderer(const std::string& graph) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the node's output is read back after the frame
  auto renderer = std::make_unique<Renderer>(options);
  renderer->set_graph(parse(graph));
  return renderer;
}

CapturedCubeSource& capture_of(Renderer& renderer) {
  return kernel_of<CapturedCubeSource>(renderer, "probes");
}

// The mean RGB of each face of probe 0's captured cube.
std::array<glm::dvec3, 6> face_means(Renderer& renderer) {
  std::array<glm::dvec3, 6> means{};
  for (int f = 0; f < 6; ++f) {
    const std::vector<float> rgba = capture_of(renderer).read_captured_face(renderer.executor().submitter(), 0, f);
    for (size_t t = 0; t < rgba.size(); t += 4)
      for (int c = 0; c < 3; ++c) means[f][c] += rgba[t + c];
    means[f] /= double(rgba.size() / 4);
  }
  return means;
}

// The reflection room without its environment, lit by its rectangle lamp alone: the raster
// capture holds each surface's direct light (lighting.deferred's formulas), the path-traced
// capture with one bounce the same light by Monte Carlo. Per face, the mean radiance of each
// channel agrees within the tolerance below. The faces see different walls (red -X, green +X,
// blue -Z, the ceiling +Y unlit by the downward lamp, the steel floor -Y), so a face drawn with
// the wrong camera or winding moves its mean by far more.
TEST(RasterCapture, FacesMatchThePathTracedCaptureUnderDirectLight) {
  World world = load_world(kRoom);
  std::vector<Entity> environments;
  world.each<EnvironmentLight>([&](Entity e, const EnvironmentLight&) { environments.push_back(e); });
  ASSERT_FALSE(environments.empty());
  for (Entity e : environments) world.remove<EnvironmentLight>(e);
  auto graph = [](const char* params) {
    return std::string(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "probes", "type": "gi.reflection_capture", "params": )") +
           params + R"( } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "probes.gbuffer" } ],
    "outputs": [ "probes.reflections" ] })";
  };
  auto raster = make_renderer(graph(R"({ "capture": "raster", "face_size": 32 })"));
  raster->render(world, kFrame);
  expect_no_validation_messages(raster->context());
  auto traced = make_renderer(graph(R"({ "capture": "path_traced", "face_size": 32, "samples": 16, "bounces": 1 })"));
  traced->render(world, kFrame);
  expect_no_validation_messages(traced->context());
  const auto a = face_means(*raster), b = face_means(*traced);
  double largest = 0.0;
  for (int f = 0; f < 6; ++f) largest = std::max({largest, b[f].x, b[f].y, b[f].z});
  for (int f = 0; f < 6; ++f) {
    std::printf("face %d: raster (%.4f %.4f %.4f) path traced (%.4f %.4f %.4f)\n", f, a[f].x, a[f].y, a[f].z, b[f].x,
                b[f].y, b[f].z);
    // Measured on the five faces of diffuse walls: within 1.5% (the path tracer's noise at 16
    // paths over 1024 texels, and lighting.deferred's area-light formulas against exact
    // integration). Allowed: 5% of the face's mean and 1% of the brightest face's. The floor's
    // face (-Y) holds the steel's glossy image of the lamp, where lighting.deferred's
    // rectangle-light specular (LTC) gives 17% more than Monte Carlo (the representative points
    // it replaced as the default, 30%): allowed 40% there. A face drawn along the wrong axis or mirrored gets another wall's
    // colour, off by several times.
    const double relative = f == 3 ? 0.4 : 0.05;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(a[f][c], b[f][c], relative * b[f][c] + 0.01 * largest) << "face " << f << " channel " << c;
  }
}

// faces_per_frame 2 on the room's one probe: a round is 3 frames. The first frame captures all;
// then the lamp brightens. After two frames (four new faces, the probe not yet prefiltered again)
// the lookup is still the first frame's; after the third it equals a whole capture of the
// brightened room. Fails if the faces were not sliced (the key change would capture everything
// at once) or if the sliced faces never reached the cube.
TEST(RasterCapture, TimeSlicedCaptureEqualsTheWholeCaptureAfterOneRound) {
  const std::string graph = read_example();
  const std::string params = R"("capture": "raster", "face_size": 128, "second_bounce": true)";
  const size_t at = graph.find(params);
  ASSERT_NE(at, std::string::npos) << "examples/reflection-probes.json no longer has the params this test edits";
  auto with = [&](const char* replacement) { return std::string(graph).replace(at, params.size(), replacement); };
  World world = load_world(kRoom);
  auto sliced = make_renderer(with(R"("capture": "raster", "face_size": 16, "faces_per_frame": 2)"));
  auto whole = make_renderer(with(R"("capture": "raster", "face_size": 16)"));
  auto reflections = [](Renderer& r) { return r.executor().read_image("probes.reflections"); };
  sliced->render(world, kFrame);
  const std::vector<float> before = reflections(*sliced);
  world.each<RectLight>([](Entity, RectLight& l) { l.intensity *= 3.0f; });
  sliced->render(world, kFrame);
  sliced->render(world, kFrame);
  const std::vector<float> partial = reflections(*sliced);
  sliced->render(world, kFrame);
  const std::vector<float> round = reflections(*sliced);
  whole->render(world, kFrame);
  const std::vector<float> expected = reflections(*whole);
  expect_no_validation_messages(sliced->context());
  expect_no_validation_messages(whole->context());
  ASSERT_EQ(round.size(), expected.size());
  double moved = 0.0, partial_off = 0.0, round_off = 0.0;
  for (size_t i = 0; i < expected.size(); ++i) {
    moved = std::max(moved, double(std::abs(expected[i] - before[i])));
    partial_off = std::max(partial_off, double(std::abs(partial[i] - before[i])));
    round_off = std::max(round_off, double(std::abs(round[i] - expected[i])));
  }
  std::printf(
      "largest change by the lamp %.4g; after 2 frames off the first %.3g; after 3 off the whole capture %.3g\n", moved,
      partial_off, round_off);
  ASSERT_GT(moved, 0.1);  // the lamp's change shows in the reflections
  // The same draws and the same prefilter on the same device: equal but for float rounding
  // (none expected; 1e-5 of the largest change allows for it).
  EXPECT_LE(partial_off, 1e-5 * moved);
  EXPECT_LE(round_off, 1e-5 * moved);
}

// The example (raster, second bounce) time-sliced one face a frame over a round and more, the
// lamp brightening each frame: every frame validation-clean, every texel finite, and the probe's
// light following the lamp (the last frame brighter than the first).
TEST(RasterCapture, TimeSlicedSecondBounceStaysCleanAndFollowsTheLight) {
  std::string graph = read_example();
  const std::string params = R"("capture": "raster", "face_size": 128, "second_bounce": true)";
  const size_t at = graph.find(params);
  ASSERT_NE(at, std::string::npos) << "examples/reflection-probes.json no longer has the params this test edits";
  graph.replace(at, params.size(),
                R"("capture": "raster", "face_size": 16, "second_bounce": true, "faces_per_frame": 1)");
  World world = load_world(kRoom);
  auto renderer = make_renderer(graph);
  double first = 0.0, last = 0.0;
  for (int frame = 0; frame < 8; ++frame) {
    renderer->render(world, kFrame);
    const std::vector<float> reflections = renderer->executor().read_image("probes.reflections");
    double sum = 0.0;
    for (float v : reflections) {
      ASSERT_TRUE(std::isfinite(v)) << "frame " << frame;
      sum += v;
    }
    (frame == 0 ? first : last) = sum;
    world.each<RectLight>([](Entity, RectLight& l) { l.intensity *= 1.2f; });
  }
  expect_no_validation_messages(renderer->context());
  // The lamp is 1.2^6 = 3 times brighter when the round's last face is drawn; the walls' light from
  // the sky's SH does not change, so the sum rises less (measured: 1.19 times). Without the sliced
  // faces reaching the lookup it would not change at all.
  EXPECT_GT(last, 1.1 * first);
}

// The reflection room's chrome ball is "captured_by_probes": false (it sits inside the probe's
// proxy, which does not model it). Every face of the raster capture (16x16, the lamp alone) equals
// the capture of the room with the ball not drawn at all, and the face the ball is on (-Y: the
// ball is below the probe) changes when the ball is captured. Fails if the capture drew it anyway.
TEST(RasterCapture, EntitiesNotCapturedByProbesAreLeftOut) {
  const char* graph = R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "probes", "type": "gi.reflection_capture", "params": { "capture": "raster", "face_size": 16 } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "probes.gbuffer" } ],
    "outputs": [ "probes.reflections" ] })";
  auto faces = [&](World world) {
    std::vector<Entity> environments;
    world.each<EnvironmentLight>([&](Entity e, const EnvironmentLight&) { environments.push_back(e); });
    for (Entity e : environments) world.remove<EnvironmentLight>(e);
    auto renderer = make_renderer(graph);
    renderer->render(world, kFrame);
    expect_no_validation_messages(renderer->context());
    std::vector<std::vector<float>> out;
    for (int f = 0; f < 6; ++f)
      out.push_back(capture_of(*renderer).read_captured_face(renderer->executor().submitter(), 0, f));
    return out;
  };
  const World room = load_world(kRoom);
  Entity ball;
  room.each<MeshRenderer>([&](Entity e, const MeshRenderer& r) {
    if (!r.captured_by_probes) ball = e;
  });
  ASSERT_FALSE(ball.is_null()) << "the reflection room no longer leaves its ball out of the captures";
  World without = load_world(kRoom), captured = load_world(kRoom);
  without.remove<MeshRenderer>(ball);
  captured.get<MeshRenderer>(ball).captured_by_probes = true;
  const auto left_out = faces(load_world(kRoom)), absent = faces(std::move(without)), seen = faces(std::move(captured));
  for (int f = 0; f < 6; ++f) EXPECT_EQ(left_out[f], absent[f]) << "face " << f;
  EXPECT_NE(seen[3], absent[3]);
}

}  // namespace
}  // namespace lg::test
