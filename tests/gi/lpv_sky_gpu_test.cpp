// gi.lpv's sky (the environment's SH linked into its sh input) on lavapipe, the sun at zero so
// that the sky is all the light:
// - inside a closed room under the sky the geometry volume hides it: the truth is 0;
// - an open floor gets about the sky's irradiance at its normal (E_sky(up) from the same SH),
//   its own reflection of the sky included;
// - the sky's march is kept while the grid, the geometry and the SH stay the same, and redone
//   (equal to a fresh renderer's) when a wall moves or the sky is animated;
// - degenerate skies (an environment of the largest floats, and the same at intensity 0) on the
//   degenerate world: every output finite, validation clean.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/gi/lpv/lpv_kernel.h"
#include "runtime/image/image_formats.h"
#include "tests/gi/camera_and_sun.h"
#include "tests/gi/covered_irradiance.h"
#include "tests/gi/degenerate_world.h"
#include "tests/gi/plan_kernel.h"
#include "tests/gi/sky_irradiance.h"
#include "tests/gi/slab_world.h"
#include "tests/gi/validating_renderer.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{64, 36};
constexpr float kWhite = 0.8f;

// gi.lpv at grid 16, 8 iterations, with the SH (order 2, cosine-convolved, as
// examples/gi-lpv.json's) of `environment`, a node's JSON, linked into its sh input.
Graph lpv_sky_graph(const std::string& environment) {
  Diagnostics d("lpv-sky-test.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      )" + environment + R"(,
      { "id": "sh", "type": "env.sh_project", "params": { "order": 2, "window": "none", "convolve_cosine": true } },
      { "id": "lpv", "type": "gi.lpv", "params": { "grid": 16, "iterations": 8, "rsm_size": 64, "resolution_scale": 1 } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "lpv.gbuffer" }, { "from": "sky.cube", "to": "sh.env" },
               { "from": "sh.sh", "to": "lpv.sh" } ],
    "outputs": [ "lpv.irradiance", "sh.sh" ] })",
                                                d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

const std::string kSky = R"({ "id": "sky", "type": "env.sky", "params": { "face_size": 16 } })";

// A camera at `eye` looking along `look`, a sun of zero intensity (it adds nothing; the sun's
// passes run as in a lit world, so the sky is measured beside them) and the environment the SH
// stands for.
void add_camera_sun_and_sky(World& world, glm::vec3 eye, glm::vec3 look) {
  add_camera_and_sun(world, eye, look, {-0.2f, -1.0f, -0.1f}, 0.0f);
  world.add(world.create("environment"), EnvironmentLight{});
}

// slab_world.h's closed room (0.1 m slabs, cells of 26 cm: each wall shares its cells with the
// room's edge) under env.sky's sky, seen from inside: the truth is 0. Measured 1.4% of the sky's
// irradiance on an open floor: 0.99% from the sky's march (rays slipping past the room's
// corners; with the cells' own surfaces read from the lobe alone 6.1%, with one plane per cell
// also at the edges 5.3%: docs/lpv.md), the rest the outer walls' reflection of the sky, whose
// propagation's first step is not blocked; bound 2%.
TEST(LpvSky, LeavesTheInsideOfAClosedRoomDark) {
  World room;
  add_closed_room(room, kWhite, 0.1f);
  add_camera_sun_and_sky(room, {0.0f, 2.5f, 1.8f}, {0.0f, -0.8f, -1.0f});
  auto renderer = make_renderer(lpv_sky_graph(kSky));
  renderer->render(room, kFrame);
  const double sky_up = sky_irradiance_green(*renderer, {0, 1, 0});
  const CoveredIrradiance inside = covered_irradiance(renderer->executor().read_image("lpv.irradiance"));
  std::printf("inside the closed room under the sky: mean E %.5f, %.3f%% of E_sky(up) %.4f\n", inside.mean_green,
              100.0 * inside.mean_green / sky_up, sky_up);
  ASSERT_EQ(inside.covered, size_t(kFrame.width) * kFrame.height);
  EXPECT_GT(sky_up, 0.0);
  EXPECT_LT(inside.mean_green, 0.02 * sky_up);
  expect_no_validation_messages(renderer->context());
}

// A white floor 8 x 8 m, 0.1 m thick, and a post 0.2 x 2 x 0.2 m at one corner, so that the grid
// (the draws' bounds) has open cells above the floor, seen from above under the sky alone.
World open_floor_under_the_sky() {
  World world;
  const auto slab = slab_adder(world, kWhite);
  slab({8.0f, 0.1f, 8.0f}, {0.0f, -0.05f, 0.0f});
  slab({0.2f, 2.0f, 0.2f}, {3.8f, 1.0f, -3.8f});
  add_camera_sun_and_sky(world, {0.0f, 3.0f, 1.0f}, {0.0f, -1.0f, -0.3f});
  return world;
}

// A floor 8 x 8 m, 0.1 m thick, under the sky, seen from above away from its edges, and a post
// 0.2 x 2 x 0.2 m at one corner, so that the grid (the draws' bounds) has open cells above the
// floor: the truth is E_sky(up) on the floor, less the post's share of the sky (under 1%: 0.4 m^2
// seen from at least 3 m), nothing coming back from the sky the floor reflects. Measured 1.117:
// 0.983 from the sky's march (32 directions sample the sky's gradient; the cells above the floor,
// whose light the lookup reads, see the sky from up to a cell above it), +0.13 the floor's own
// reflection of the sky, which the propagation's cosine lobes spread partly back down onto it
// (docs/lpv.md). Tolerance 15%.
TEST(LpvSky, GivesAnOpenFloorTheSkysIrradiance) {
  World world = open_floor_under_the_sky();
  auto renderer = make_renderer(lpv_sky_graph(kSky));
  renderer->render(world, kFrame);
  const double sky_up = sky_irradiance_green(*renderer, {0, 1, 0});
  const CoveredIrradiance floor = covered_irradiance(renderer->executor().read_image("lpv.irradiance"));
  std::printf("open floor under the sky: mean E %.4f, E_sky(up) %.4f, ratio %.3f\n", floor.mean_green, sky_up,
              floor.mean_green / sky_up);
  ASSERT_EQ(floor.covered, size_t(kFrame.width) * kFrame.height);
  EXPECT_NEAR(floor.mean_green / sky_up, 1.0, 0.15);
  expect_no_validation_messages(renderer->context());
}

// The volume output (the inspector's view of the grid) holds the sky's light as the lookup reads
// it: the open floor above, rendered with the SH linked and without. The sky adds and never takes
// away (its march and its bounce are sources of positive light: every cell at least as bright, to
// the half floats' rounding), and a cell of the grid's top layer above the floor's middle gains
// the mean over all normals of the irradiance from what it sees, a quarter of the radiance's
// integral over those directions: from the sky above, a quarter of 2 pi L for a uniform sky (half
// of E_sky(up)) down to a quarter of E_sky(up) for a sky whose light comes from straight above,
// plus the floor's reflection of it from below (up to kWhite / 2 of E_sky(up)); bounds 0.25 and
// 1.0 of E_sky(up). Without the sky in the view (before stop 34) the gain was the bounce alone.
TEST(LpvSky, TheVolumeOutputHoldsTheSky) {
  World world = open_floor_under_the_sky();
  auto volume_of = [&](bool sky_linked, double* sky_up) {
    Graph graph = lpv_sky_graph(kSky);
    if (!sky_linked) std::erase_if(graph.links, [](const GraphLink& l) { return l.to.text() == "lpv.sh"; });
    graph.outputs.push_back({{"lpv", "volume"}, {}});
    auto renderer = make_renderer(graph);
    renderer->render(world, kFrame);
    if (sky_up) *sky_up = sky_irradiance_green(*renderer, {0, 1, 0});
    expect_no_validation_messages(renderer->context());
    return renderer->executor().read_image("lpv.volume");
  };
  double sky_up = 0;
  const std::vector<float> with = volume_of(true, &sky_up), without = volume_of(false, nullptr);
  ASSERT_EQ(with.size(), without.size());
  const int n = int(std::lround(std::cbrt(double(with.size() / 4))));  // grid^3 texels
  ASSERT_EQ(size_t(n) * n * n * 4, with.size());
  auto at = [&](int x, int y, int z) { return 4 * ((size_t(z) * n + y) * n + x); };
  int top = -1;  // the grid's top layer of cells
  for (int y = 0; y < n; ++y)
    if (with[at(n / 2, y, n / 2) + 3] > 0.5f) top = y;
  ASSERT_GT(top, 0);
  size_t darker = 0;
  for (size_t i = 0; i < with.size(); i += 4) darker += with[i + 1] < without[i + 1] - 1e-3 * sky_up;
  double gain = 0;
  int cells = 0;
  for (int z = n / 4; z < 3 * n / 4; ++z)
    for (int x = n / 4; x < 3 * n / 4; ++x, ++cells) gain += with[at(x, top, z) + 1] - without[at(x, top, z) + 1];
  gain /= cells;
  std::printf("the volume's top layer gains %.4f with the sky (E_sky(up) %.4f, ratio %.3f); cells darker: %zu\n",
              gain, sky_up, gain / sky_up, darker);
  EXPECT_EQ(darker, 0u);
  EXPECT_GT(gain, 0.25 * sky_up);
  EXPECT_LT(gain, 1.0 * sky_up);
}

// How many frames marched the sky in `renderer`'s gi.lpv (its kernel counts them).
uint64_t sky_marches(Renderer& renderer) {
  return kernel_of<LpvBuilds>(renderer, "lpv").sky_marches();
}

// `world`'s irradiance from a renderer of its own, which marches the sky afresh.
std::vector<float> fresh_irradiance(const Graph& graph, const World& world) {
  auto fresh = make_renderer(graph);
  fresh->render(world, kFrame);
  EXPECT_EQ(sky_marches(*fresh), 1u);
  expect_no_validation_messages(fresh->context());
  return fresh->executor().read_image("lpv.irradiance");
}

// A still scene's second frame keeps the first's march (the kernel's count stays at one) and
// equals the first exactly; so does a frame whose camera moved (the march is of the grid, not
// the view), which equals a fresh renderer's frame of the moved camera exactly (the march is
// deterministic: integer atomics and per-cell stores, so kept and redone images are the same).
TEST(LpvSky, KeepsItsMarchWhileTheGridTheGeometryAndTheSkyStay) {
  World world = open_floor_under_the_sky();
  const Graph graph = lpv_sky_graph(kSky);
  auto renderer = make_renderer(graph);
  renderer->render(world, kFrame);
  const std::vector<float> first = renderer->executor().read_image("lpv.irradiance");
  renderer->render(world, kFrame);
  EXPECT_EQ(sky_marches(*renderer), 1u);
  EXPECT_EQ(renderer->executor().read_image("lpv.irradiance"), first);
  world.each<Camera>([&](Entity camera, Camera&) { world.get<Transform>(camera).position.x += 0.5f; });
  renderer->render(world, kFrame);
  EXPECT_EQ(sky_marches(*renderer), 1u);
  const std::vector<float> moved = renderer->executor().read_image("lpv.irradiance");
  EXPECT_NE(moved, first);  // the view did change
  EXPECT_EQ(moved, fresh_irradiance(graph, world));
  expect_no_validation_messages(renderer->context());
}

// The post moved 1 m towards the floor's middle (the grid, the draws' bounds, stays the same)
// marches again, and the frame equals a fresh renderer's exactly (as above); a march kept from
// before would still hide the sky where the post stood.
TEST(LpvSky, MarchesAgainWhenAWallMoves) {
  World world = open_floor_under_the_sky();
  const Graph graph = lpv_sky_graph(kSky);
  auto renderer = make_renderer(graph);
  renderer->render(world, kFrame);
  const std::vector<float> before = renderer->executor().read_image("lpv.irradiance");
  int moved = 0;
  world.each<Transform>([&](Entity, Transform& t) {
    if (t.position == glm::vec3(3.8f, 1.0f, -3.8f)) t.position.x -= 1.0f, ++moved;
  });
  ASSERT_EQ(moved, 1);
  renderer->render(world, kFrame);
  EXPECT_EQ(sky_marches(*renderer), 2u);
  const std::vector<float> after = renderer->executor().read_image("lpv.irradiance");
  EXPECT_NE(after, before);  // the post's move does change the frame
  EXPECT_EQ(after, fresh_irradiance(graph, world));
  expect_no_validation_messages(renderer->context());
}

// An animated sky (env.sky turning its sun: its SH is not a static result, so it may change in
// any frame) is marched every frame; at 0 s a frame the sun stays put, so every frame equals a
// fresh renderer's.
TEST(LpvSky, MarchesAnAnimatedSkyEveryFrame) {
  World world = open_floor_under_the_sky();
  const Graph graph =
      lpv_sky_graph(R"({ "id": "sky", "type": "env.sky", "params": { "face_size": 16, "sun_turn_speed": 10 } })");
  auto renderer = make_renderer(graph);
  for (int frame = 0; frame < 2; ++frame) renderer->render(world, kFrame, {.seconds = 0.0f});
  EXPECT_EQ(sky_marches(*renderer), 2u);
  EXPECT_EQ(renderer->executor().read_image("lpv.irradiance"), fresh_irradiance(graph, world));
  expect_no_validation_messages(renderer->context());
}

// Degenerate skies on the degenerate world (zero-area triangles, a NaN colour, a 1e30 sun): an
// environment of the largest finite floats (env.load keeps it within the half floats: the SH's
// first coefficient reads 7.3e5, some 10^5 times a daylight sky's) and the same at intensity 0
// (an SH of zeros). Every output value finite, validation clean; the graph's env nodes never
// hand on a non-finite SH (env.sh_project counts such texels as 0), and lpv_sky.comp zeroes
// non-finite coefficients besides.
TEST(LpvSky, StaysFiniteOnADegenerateSky) {
  const std::filesystem::path path = std::filesystem::path(LUMAGRAPH_BINARY_DIR) / "lpv-sky-test-huge.exr";
  const float huge = std::numeric_limits<float>::max();
  std::vector<float> texels(8 * 4 * 4, huge);
  write_exr(path.string(), 8, 4, texels, false, true);
  for (const char* intensity : {"1", "0"}) {
    World world = degenerate_world();
    world.add(world.create("environment"), EnvironmentLight{});
    auto renderer = make_renderer(lpv_sky_graph(R"({ "id": "sky", "type": "env.load", "params": { "path": ")" +
                                                path.string() + R"(", "face_size": 8, "intensity": )" + intensity +
                                                " } }"));
    renderer->render(world, kFrame);
    const std::vector<std::byte> sh = renderer->executor().read_buffer("sh.sh");
    float first[4];
    std::memcpy(first, sh.data(), sizeof(first));
    std::printf("intensity %s: the SH's first coefficient %g %g %g\n", intensity, first[0], first[1], first[2]);
    const CoveredIrradiance out = covered_irradiance(renderer->executor().read_image("lpv.irradiance"));
    EXPECT_EQ(out.non_finite, 0u);
    EXPECT_GT(out.covered, 0u);
    expect_no_validation_messages(renderer->context());
  }
}

}  // namespace
}  // namespace lg::test
