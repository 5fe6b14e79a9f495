// gi.irradiance_volume on lavapipe against the CPU lookup (nodes/gi/probes/probe_lookup.h) on the
// Cornell box with two overlapping volumes and a third inside a block (every probe off); the
// coverage outside every volume and on the sky; the blend across a volume's border; a probe-less
// scene bypassing the node; lighting.ibl taking a volume's light in a scene without environment.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <thread>

#include "api/renderer.h"
#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"
#include "nodes/common/camera_constants.h"
#include "nodes/common/gbuffer_normal.h"
#include "nodes/gi/probes/probe_bake.h"
#include "nodes/gi/probes/probe_lookup.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{96, 72};
constexpr ProbeBakeSettings kBake{.rays = 64, .bounces = 2, .seed = 3};

Graph volume_graph(const std::string& params) {
  Diagnostics d("irradiance-volume-test.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "volume", "type": "gi.irradiance_volume", "params": )" +
                                                    params + R"( } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "volume.gbuffer" } ],
    "outputs": [ "volume.irradiance" ] })",
                                                d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

void add_volume(World& world, glm::vec3 position, glm::vec3 size, glm::ivec3 counts) {
  Entity e = world.create("volume");
  world.add(e, Transform{}).position = position;
  world.add(e, IrradianceVolume{size, counts});
}

// The Cornell box's own 8x8x8 volume, a 4x4x4 one overlapping its right half (blending across
// its border in view), and a 2x2x2 one inside the tall block (all probes off).
World cornell_box() {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  add_volume(world, {0.45f, 1.0f, 0.0f}, {0.9f, 1.2f, 1.2f}, {4, 4, 4});
  add_volume(world, {-0.33f, 0.6f, -0.3f}, {0.1f, 0.1f, 0.1f}, {2, 2, 2});
  return world;
}

struct Frame {
  std::vector<float> irradiance, depth, normal;
  SceneView view;
};

Frame render(const World& world, const std::string& params, FrameSize size = kFrame) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the G-buffer is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(volume_graph(params));
  renderer.render(world, size);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  return {renderer.executor().read_image("volume.irradiance"), renderer.executor().read_image("gbuf.gbuffer.depth"),
          renderer.executor().read_image("gbuf.gbuffer.normal"), renderer.scene_view()};
}

// What the pass computes at pixel (x, y), in double precision from the same G-buffer texels
// (camera.glsl's world_position, gbuffer.glsl's decode_normal).
struct PixelInput {
  bool sky = true;
  glm::dvec3 position{0.0}, normal{0.0, 0.0, 1.0};
};
PixelInput pixel_input(const Frame& f, const CameraConstants& c, uint32_t x, uint32_t y) {
  const size_t i = 4 * (size_t(y) * kFrame.width + x);
  PixelInput in;
  const double depth = f.depth[i];
  if (depth <= 0.0) return in;
  in.sky = false;
  const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) * glm::dvec2(c.viewport.z, c.viewport.w) * 2.0 - 1.0;
  const glm::dvec4 p = glm::dmat4(c.inverse_view_projection) * glm::dvec4(ndc, depth, 1.0);
  in.position = glm::dvec3(p) / p.w;
  in.normal = decode_gbuffer_normal(&f.normal[i]);
  return in;
}

std::vector<ProbeGrid> bake_on_cpu(const SceneView& view) {
  const PathScene scene(view, PathEnvironment::none());  // the test graph has no environment node
  std::vector<ProbeGrid> grids;
  for (const IrradianceVolumeData& v : view.irradiance_volumes) {
    ProbeGrid& g = grids.emplace_back(v);
    bake_probes(scene, g, kBake, 0, g.probe_count());
  }
  return grids;
}

// Per pixel the GPU's irradiance and coverage, at full resolution, against lookup_volumes() on the
// same probes (the bake is deterministic). The output is half float (relative step 2^-11 =
// 0.05%), so are the probes' irradiance texels in their atlas (another 0.05%; the distance
// moments are 32-bit), the atlas' borders make the sampler's bilinear fetch read the CPU's taps
// (probe_atlas_test.cpp), and the pass runs in float: positions from depth, the bilinear weights,
// the octahedral coordinates and the Chebyshev ratio carry float
// rounding that moves weights by ~1e-5 relative. 1% of the pixel's value plus 0.1% of the image
// mean bounds both with a wide margin, and the lookup is continuous in its inputs (no branch
// jumps: trilinear, wrap, Chebyshev and crush weights all are), so no pixel may exceed it.
TEST(IrradianceVolume, GpuLookupMatchesTheCpuLookup) {
  const World world = cornell_box();
  for (const char* representation : {"octahedral", "sh_l2", "ambient_cube", "sh_l1"}) {
    const bool visibility = std::string(representation) == "octahedral";
    const Frame f = render(world, std::string(R"({ "rays": 64, "bounces": 2, "seed": 3, "resolution_scale": 1,
                                                  "representation": ")") +
                                      representation + R"(", "visibility": )" + (visibility ? "true" : "false") + "}");
    ASSERT_EQ(f.view.irradiance_volumes.size(), 3u);
    static const std::vector<ProbeGrid> grids = bake_on_cpu(f.view);
    const CameraConstants c = camera_constants(f.view.camera, kFrame.width, kFrame.height);
    ProbeLookupSettings s;
    s.representation = *parse_probe_representation(representation);
    s.visibility = visibility;
    std::vector<VolumeIrradiance> expected;
    double mean = 0.0;
    for (uint32_t y = 0; y < kFrame.height; ++y)
      for (uint32_t x = 0; x < kFrame.width; ++x) {
        const PixelInput in = pixel_input(f, c, x, y);
        expected.push_back(in.sky ? VolumeIrradiance{}
                                  : lookup_volumes(grids, in.position, in.normal, glm::dvec3(c.position), s));
        mean += (expected.back().irradiance.r + expected.back().irradiance.g + expected.back().irradiance.b) / 3.0;
      }
    mean /= double(expected.size());
    ASSERT_GT(mean, 0.0);
    double worst = 0.0;
    size_t bad = 0, partial = 0;
    for (size_t p = 0; p < expected.size(); ++p) {
      const float* gpu = &f.irradiance[4 * p];
      for (int k = 0; k < 4; ++k) ASSERT_TRUE(std::isfinite(gpu[k])) << "pixel " << p;
      const double coverage_error = std::abs(gpu[3] - expected[p].coverage);
      partial += expected[p].coverage > 0.0 && expected[p].coverage < 1.0;
      double e = coverage_error / 0.01;
      for (int k = 0; k < 3; ++k)
        e = std::max(e, std::abs(gpu[k] - expected[p].irradiance[k]) /
                            (0.01 * std::abs(expected[p].irradiance[k]) + 0.001 * mean));
      worst = std::max(worst, e);
      bad += e > 1.0;
    }
    std::printf(
        "%s (visibility %s): mean E %.4f W/m^2, worst error %.3f of the tolerance, %zu pixels past it, "
        "%zu pixels partly covered\n",
        representation, visibility ? "on" : "off", mean, worst, bad, partial);
    EXPECT_EQ(bad, 0u) << representation;
  }
}

// resolution_scale 0.5 on the Cornell box at 320x180 against the full-resolution lookup, both on
// the same bake. At the pixels the half-resolution lookup ran at (even x and y) the upsample
// returns its texel, which is the full-resolution lookup there: equal to half-float rounding
// (0.1%). Between them it interpolates along surfaces. Measured: relative RMS 1.6% over the
// covered pixels, 0.5% of them off by more than 10% of their value (next to creases and
// silhouettes); a plain bilinear upsample (no depth and normal guide) gives 5.3% and 4.0%.
// Bounds: 3% and 1.5%.
TEST(IrradianceVolume, HalfResolutionUpsampleStaysNearFullResolution) {
  const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  const std::string bake = R"("rays": 64, "bounces": 2, "seed": 3)";
  constexpr FrameSize size{320, 180};
  const Frame full = render(world, "{ " + bake + R"(, "resolution_scale": 1 })", size);
  const Frame half = render(world, "{ " + bake + R"(, "resolution_scale": 0.5 })", size);
  double difference = 0.0, magnitude = 0.0, worst_sampled = 0.0;
  size_t pixels = 0, off = 0;
  for (uint32_t y = 0; y < size.height; ++y)
    for (uint32_t x = 0; x < size.width; ++x) {
      const float* a = &full.irradiance[4 * (size_t(y) * size.width + x)];
      const float* b = &half.irradiance[4 * (size_t(y) * size.width + x)];
      for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(b[c]));
      double d2 = 0.0, m2 = 0.0;
      for (int c = 0; c < 3; ++c) d2 += std::pow(b[c] - a[c], 2.0), m2 += std::pow(a[c], 2.0);
      if (x % 2 == 0 && y % 2 == 0) {
        for (int c = 0; c < 4; ++c)
          worst_sampled = std::max(worst_sampled, std::abs(b[c] - a[c]) / (std::abs(a[c]) + 1e-6));
      }
      if (a[3] == 0.0f && b[3] == 0.0f) continue;
      difference += d2, magnitude += m2;
      ++pixels;
      off += d2 > 0.01 * m2;
    }
  const double rms = std::sqrt(difference / magnitude), share = double(off) / double(pixels);
  std::printf("half resolution: relative RMS %.4f, %zu of %zu pixels off by more than 10%%, worst sampled pixel %.2e\n",
              rms, off, pixels, worst_sampled);
  EXPECT_LT(worst_sampled, 1e-3);
  EXPECT_LT(rms, 0.03);
  EXPECT_LT(share, 0.015);
}

// The Cornell box's sky around the room and a volume covering only the room's left part: where
// the G-buffer has no surface, or the point lies beyond the volume's fade (the box grown by three
// quarters of a cell), the coverage is exactly 0 (and the irradiance too); where it serves in
// full, 1. At full resolution: below it the
// upsample blends the coverage across a volume's border.
TEST(IrradianceVolume, CoverageIsZeroOutsideEveryVolumeAndOnTheSky) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  world.each<IrradianceVolume>([](Entity, IrradianceVolume& v) { v.size = {0.6f, 1.9f, 1.9f}; });
  world.each<IrradianceVolume>([&](Entity e, IrradianceVolume&) { world.get<Transform>(e).position.x = -0.6f; });
  const Frame f = render(world, R"({ "rays": 32, "bounces": 1, "resolution_scale": 1 })");
  const CameraConstants c = camera_constants(f.view.camera, kFrame.width, kFrame.height);
  const ProbeGrid grid(f.view.irradiance_volumes[0]);
  size_t sky = 0, outside = 0, inside = 0;
  for (uint32_t y = 0; y < kFrame.height; ++y)
    for (uint32_t x = 0; x < kFrame.width; ++x) {
      const float* gpu = &f.irradiance[4 * (size_t(y) * kFrame.width + x)];
      const PixelInput in = pixel_input(f, c, x, y);
      const double margin = volume_margin(grid.grid_coordinates(in.position), grid.counts());
      if (in.sky || margin < -1e-3) {
        (in.sky ? sky : outside) += 1;
        EXPECT_EQ(gpu[3], 0.0f) << x << ", " << y;
        EXPECT_EQ(gpu[0] + gpu[1] + gpu[2], 0.0f) << x << ", " << y;
      } else if (margin > kVolumeBlendRamp + 1e-3) {
        inside += gpu[3] == 1.0f;
      }
    }
  std::printf("sky pixels %zu, outside %zu, fully covered %zu\n", sky, outside, inside);
  EXPECT_GT(sky, 0u);
  EXPECT_GT(outside, 100u);
  EXPECT_GT(inside, 100u);
}

// Two volumes whose probes hold constant irradiance 1 and 3 overlap along x; walking across both
// borders the blend moves from 1 to 3 without a jump (a change per 0.001-cell step under 0.05,
// where a seam would jump by 1 or more; the steepest the smoothstep allows is about 0.012), and
// the coverage falls to 0 only past the outer border, no faster than the smoothstep's slope.
TEST(IrradianceVolume, OverlappingVolumesBlendContinuously) {
  auto constant_grid = [](double x, float e) {
    IrradianceVolumeData v;
    v.world = glm::translate(glm::mat4(1.0f), glm::vec3(float(x), 0.0f, 0.0f));
    v.size = glm::vec3(2.0f);
    v.probe_counts = glm::ivec3(3);
    ProbeGrid g(v);
    for (ProbeData& p : g.probes) {
      p.active = true;
      p.irradiance.fill(glm::vec3(e));
      p.distance.fill(glm::vec2(10.0f, 100.0f));  // open space: nothing nearer than 10
    }
    return g;
  };
  const std::vector<ProbeGrid> grids = {constant_grid(0.0, 1.0f), constant_grid(1.5, 3.0f)};
  const double step = 0.001;  // cells are 1 wide
  double previous = 1.0, previous_coverage = 1.0, largest_jump = 0.0;
  for (double x = -0.5; x <= 3.5; x += step) {  // from where the second volume's fade begins
    const VolumeIrradiance e = lookup_volumes(grids, {x, 0.0, 0.0}, {0, 1, 0}, {x, 5.0, 0.0}, {});
    ASSERT_TRUE(std::isfinite(e.irradiance.g));
    if (e.coverage > 0.0) {
      EXPECT_GE(e.irradiance.g, 1.0 - 1e-9);
      EXPECT_LE(e.irradiance.g, 3.0 + 1e-9);
      largest_jump = std::max(largest_jump, std::abs(e.irradiance.g - previous));
      previous = e.irradiance.g;
    }
    EXPECT_LE(std::abs(e.coverage - previous_coverage), 1.5 / kVolumeBlendRamp * step + 1e-9) << x;
    previous_coverage = e.coverage;
    // Both volumes serve in full up to half a cell past the second's last probe (x = 2.5), and
    // nothing reaches beyond the fade a quarter cell further.
    if (x < 1.5 + 1.0 + kVolumeServedCells - 1e-6) {
      EXPECT_EQ(e.coverage, 1.0) << x;
    }
    if (x > 1.5 + 1.0 + kVolumeServedCells + kVolumeBlendRamp + 1e-6) {
      EXPECT_EQ(e.coverage, 0.0) << x;
    }
  }
  EXPECT_NEAR(previous, 3.0, 1e-9);
  EXPECT_LT(largest_jump, 0.05);
}

// The documented contract: walls up to half a cell beyond the outermost probes are served in
// full. The Cornell box's volume (1.9 m of probes in a 2 m room, the walls 5 cm beyond its outer
// probes) at half, one and twice its density: the walls lie 0.08, 0.18 and 0.37 cells out. With
// the fade inside that half cell, the 15-probe grid's walls had coverage 0.54, and the sky's
// ambient, mixed in for the rest, made the room a quarter too bright; also a point 0.499 cells
// out.
TEST(IrradianceVolume, WallsWithinHalfACellOfTheProbesAreServedInFull) {
  for (int probes : {4, 8, 15}) {
    IrradianceVolumeData v;
    v.size = glm::vec3(1.9f);
    v.probe_counts = glm::ivec3(probes);
    ProbeGrid grid(v);
    for (ProbeData& p : grid.probes) {
      p.active = true;
      p.irradiance.fill(glm::vec3(1.0f));
      p.distance.fill(glm::vec2(10.0f, 100.0f));  // open space: nothing nearer than 10
    }
    const double edge = 0.95 + 0.499 * grid.min_spacing();
    for (const glm::dvec3& wall : {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, -1.0, 0.3), glm::dvec3(-1.0, 1.0, 1.0),
                                   glm::dvec3(0.2, 0.1, edge)}) {
      const VolumeIrradiance e = lookup_volumes(std::span(&grid, 1), wall, -glm::normalize(wall), {0, 0, 0}, {});
      EXPECT_EQ(e.coverage, 1.0) << probes << " probes, at " << wall.x << ", " << wall.y << ", " << wall.z;
    }
  }
}

// Every probe off (inside geometry), or probes whose distance moments are all zero (a probe in a
// wall sees distance 0 everywhere): finite, and no light where nothing is on.
TEST(IrradianceVolume, ProbesOffOrInsideGeometryGiveNoNaN) {
  IrradianceVolumeData v;
  v.probe_counts = glm::ivec3(2);
  ProbeGrid off(v), walled(v);
  for (ProbeData& p : walled.probes) p.active = true, p.irradiance.fill(glm::vec3(2.0f));
  for (const glm::dvec3& point : {glm::dvec3(0.0), glm::dvec3(0.5), glm::dvec3(-0.49, 0.2, 0.1)}) {
    const VolumeIrradiance a = lookup_volumes(std::span(&off, 1), point, {0, 0, 1}, {0, 0, 5}, {});
    EXPECT_EQ(a.coverage, 0.0);
    EXPECT_EQ(a.irradiance, glm::dvec3(0.0));
    const VolumeIrradiance b = lookup_volumes(std::span(&walled, 1), point, {0, 0, 1}, {0, 0, 5}, {});
    EXPECT_TRUE(std::isfinite(b.irradiance.r) && std::isfinite(b.coverage));
    EXPECT_NEAR(b.irradiance.r, 2.0, 1e-9);  // all probes alike: any weights give their value
  }
}

// The in-graph bake is kept while the scene stands still and redone when a light changes: the
// Cornell box's lamp at half its radiance halves the bounce light it gives (the sun's part
// stays), so the mean irradiance falls; back at full radiance the probes are baked again
// and, the bake being deterministic, the image is the first one bit for bit.
TEST(IrradianceVolume, TheBakeFollowsTheLights) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  RendererOptions options;
  options.device.validation = true;
  Renderer renderer(options);
  renderer.set_graph(volume_graph(R"({ "rays": 32, "bounces": 1 })"));
  auto mean_green = [&] {
    renderer.render(world, kFrame);
    const std::vector<float> e = renderer.executor().read_image("volume.irradiance");
    double sum = 0.0;
    for (size_t p = 0; p < e.size(); p += 4) sum += e[p + 1];
    return sum / double(e.size() / 4);
  };
  auto set_lamp = [&](float scale) {
    world.each<RectLight>([&](Entity, RectLight& l) { l.intensity = 15.0f * scale; });
  };
  const double first = mean_green(), again = mean_green();
  set_lamp(0.5f);
  const double dimmed = mean_green();
  set_lamp(1.0f);
  const double restored = mean_green();
  std::printf("mean irradiance (green): %.5f, unchanged %.5f, lamp halved %.5f, restored %.5f\n", first, again, dimmed,
              restored);
  EXPECT_EQ(again, first);
  EXPECT_LT(dimmed, 0.9 * first);
  EXPECT_EQ(restored, first);
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
}

// The dynamic mode (docs/probes.md): after the Cornell box's lamp moves toward a back corner,
// the next frame still shows the old probes (finite, and as far from the static mode's bake of
// the moved lamp as before: no frame waits for a bake), and as batches of updates land from the
// worker thread the image's mean irradiance per channel comes within 4% of that bake's (it starts
// 13% off). Every probe is in every batch here (512 of 512, 128 rays, hysteresis 0.5); both carry
// 16 bounces' worth of light (the updates' feedback carries any number). Measured: 2.3% after a
// few batches (the updates' noise keeps the means moving by about 1%). Means, not pixels: without
// a sky, two 256-ray bakes of different seeds already differ by 16% RMS per pixel here. Frames
// sleep 5 ms so the batches get the cores; the loop ends at the first frame within the bound (at
// most 3,000 frames; no time is asserted).
TEST(IrradianceVolume, DynamicModeConvergesAfterALightMovesWithoutStallingAFrame) {
  auto move_lamp = [](World& world) {
    world.each<RectLight, Transform>([](Entity, RectLight&, Transform& t) { t.position = {0.65f, 1.99f, -0.6f}; });
  };
  const std::string bake = R"("rays": 256, "bounces": 16, "seed": 3)";
  World moved = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  move_lamp(moved);
  const std::vector<float> target = render(moved, "{" + bake + "}").irradiance;
  // The largest relative difference of a channel's mean from the target's.
  auto mean_error = [&](const std::vector<float>& e) {
    glm::dvec3 a(0.0), b(0.0);
    for (size_t p = 0; p < e.size(); p += 4)
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(e[p + c])) return std::numeric_limits<double>::infinity();
        a[c] += e[p + c], b[c] += target[p + c];
      }
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] / b[c] - 1.0));
    return worst;
  };

  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  RendererOptions options;
  options.device.validation = true;
  Renderer renderer(options);
  renderer.set_graph(volume_graph("{" + bake + R"(, "mode": "dynamic", "probes_per_frame": 512, "update_rays": 128,
                                                   "hysteresis": 0.5 })"));
  auto frame = [&] {
    renderer.render(world, kFrame);
    return renderer.executor().read_image("volume.irradiance");
  };
  const double before = mean_error(frame());
  move_lamp(world);
  const std::vector<float> first = frame();
  const double first_error = mean_error(first);
  ASSERT_TRUE(std::isfinite(first_error));
  EXPECT_GT(first_error, 0.8 * before);  // not baked again in the frame
  ASSERT_GT(first_error, 0.08);          // the move must matter for the test to say anything
  double error = first_error;
  int frames = 1;
  bool changed = false;
  for (; frames < 3000 && error > 0.04; ++frames) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const std::vector<float> e = frame();
    error = mean_error(e);
    ASSERT_TRUE(std::isfinite(error)) << "frame " << frames;
    changed = changed || e != first;
  }
  std::printf(
      "dynamic mode against the moved lamp's bake, worst channel mean: %.1f%% before the move, %.1f%% in the "
      "frame after it, %.1f%% after %d frames\n",
      100.0 * before, 100.0 * first_error, 100.0 * error, frames);
  EXPECT_TRUE(changed);
  EXPECT_LE(error, 0.04);
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
}

// settle_sweeps (docs/probes.md): once the probes have had that many sweeps of updates on an
// unchanged scene, no batch starts, so the frames show the same irradiance bit for bit however
// long the worker is given (3 s of frames here, many batches' time at 32 rays a probe); moving
// the lamp starts the updates again. Every probe is in every batch (512 of 512), so 2 sweeps
// are 2 batches, each an upload that changes the image. Without the pause each further batch
// lands new noise and the frames keep changing.
TEST(IrradianceVolume, DynamicModePausesOnceSettledAndResumesWhenTheSceneChanges) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  RendererOptions options;
  options.device.validation = true;
  Renderer renderer(options);
  renderer.set_graph(volume_graph(R"({ "rays": 64, "bounces": 2, "seed": 3, "mode": "dynamic",
                                       "probes_per_frame": 512, "update_rays": 32, "settle_sweeps": 2 })"));
  auto frame = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));  // the batches get the cores
    renderer.render(world, kFrame);
    return renderer.executor().read_image("volume.irradiance");
  };
  std::vector<float> last = frame();  // the bake
  int uploads = 0;
  for (int f = 0; f < 3000 && uploads < 2; ++f)
    if (std::vector<float> e = frame(); e != last) ++uploads, last = std::move(e);
  ASSERT_EQ(uploads, 2);
  int frames = 0;
  for (const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
       std::chrono::steady_clock::now() < until; ++frames)
    ASSERT_EQ(frame(), last) << "a batch landed after the probes settled, frame " << frames;
  world.each<RectLight, Transform>([](Entity, RectLight&, Transform& t) { t.position = {0.65f, 1.99f, -0.6f}; });
  bool resumed = false;
  for (int f = 0; f < 3000 && !resumed; ++f) resumed = frame() != last;
  std::printf("settled after 2 uploads, unchanged over %d frames, resumed after the lamp moved: %s\n", frames,
              resumed ? "yes" : "no");
  EXPECT_TRUE(resumed);
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
}

// lighting.ibl with a volume linked, in the Cornell box without its environment (a room lit by
// its lamp and the sun alone): the node is not bypassed; where the volume covers a surface the
// image-based light is the volume's bounce light (ibl.color above the direct light on at least
// 90% of the covered pixels, which are about half the image), and where it covers nothing the
// environment counts 0, so the colour is the direct light's to half-float rounding (0.1%).
TEST(IrradianceVolume, LightingIblTakesTheVolumeInASceneWithoutEnvironment) {
  World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  std::vector<Entity> environments;
  world.each<EnvironmentLight>([&](Entity e, EnvironmentLight&) { environments.push_back(e); });
  for (Entity e : environments) world.destroy(e);
  Diagnostics d("ibl-volume-test.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "sky", "type": "env.sky", "params": { "face_size": 16 } },
      { "id": "sh", "type": "env.sh_project", "params": { "convolve_cosine": true } },
      { "id": "specular", "type": "env.specular_prefilter", "params": { "face_size": 8, "mips": 2, "samples": 4 } },
      { "id": "dfg", "type": "env.brdf_lut", "params": { "size": 8, "samples": 16 } },
      { "id": "light", "type": "lighting.deferred" },
      { "id": "volume", "type": "gi.irradiance_volume", "params": { "rays": 32, "bounces": 1 } },
      { "id": "ibl", "type": "lighting.ibl" } ],
    "links": [ { "from": "sky.cube", "to": "sh.env" }, { "from": "sky.cube", "to": "specular.env" },
      { "from": "gbuf.gbuffer", "to": "light.gbuffer" }, { "from": "gbuf.gbuffer", "to": "volume.gbuffer" },
      { "from": "gbuf.gbuffer", "to": "ibl.gbuffer" }, { "from": "light.color", "to": "ibl.direct" },
      { "from": "sh.sh", "to": "ibl.sh" }, { "from": "specular.specular", "to": "ibl.specular" },
      { "from": "dfg.lut", "to": "ibl.brdf_lut" }, { "from": "volume.irradiance", "to": "ibl.irradiance_volume" } ],
    "outputs": [ "ibl.color" ] })",
                                                d);
  ASSERT_TRUE(graph) << d.to_string();
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // every image is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(std::move(*graph));
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  const std::vector<float> color = renderer.executor().read_image("ibl.color");
  const std::vector<float> direct = renderer.executor().read_image("light.color");
  const std::vector<float> volume = renderer.executor().read_image("volume.irradiance");
  size_t covered = 0, brighter = 0, uncovered = 0;
  for (size_t p = 0; p < color.size() / 4; ++p) {
    if (volume[4 * p + 3] > 0.0f) {
      ++covered;
      brighter += color[4 * p + 1] > direct[4 * p + 1];
      continue;
    }
    ++uncovered;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(color[4 * p + c], direct[4 * p + c], 1e-3 * std::abs(direct[4 * p + c]) + 1e-6) << p;
  }
  std::printf("covered %zu (brighter than direct: %zu), uncovered %zu\n", covered, brighter, uncovered);
  EXPECT_GT(covered, color.size() / 4 / 3);
  EXPECT_GE(brighter, covered * 9 / 10);
}

// Compiling examples/gi-volume.json: a scene without volumes bypasses the volume node with the
// reason, and lighting.ibl takes nothing from it; a scene with volumes but without an environment
// keeps lighting.ibl (a sealed room lit by lamps still has bounce light).
TEST(IrradianceVolume, ProbelessSceneBypassesTheNode) {
  Diagnostics d;
  std::optional<Graph> graph = load_graph_file(LUMAGRAPH_SOURCE_DIR "/examples/gi-volume.json", d);
  ASSERT_TRUE(graph) << d.to_string();
  auto state_of = [](const Plan& plan, const std::string& id) {
    for (const PlanNode& n : plan.nodes)
      if (n.id == id) return std::pair{n.state, n.reason};
    return std::pair{NodeState::Kind::culled, std::string("missing")};
  };
  auto lookup_passes = [](const Plan& plan) {
    return std::count_if(plan.passes.begin(), plan.passes.end(),
                         [](const PlanPass& p) { return p.name == "volume/lookup"; });
  };
  CompileOptions options;
  options.scene = default_scene_summary();
  options.scene.irradiance_volumes = 0;
  CompileResult none = compile(*graph, builtin_registry(), options, d);
  ASSERT_TRUE(none.plan) << d.to_string();
  EXPECT_EQ(state_of(*none.plan, "volume").first, NodeState::Kind::bypassed);
  EXPECT_EQ(state_of(*none.plan, "volume").second, "the scene has no irradiance volumes");
  EXPECT_EQ(lookup_passes(*none.plan), 0);
  EXPECT_EQ(state_of(*none.plan, "ibl").first, NodeState::Kind::active);

  options.scene.irradiance_volumes = 1;
  options.scene.environment = false;
  CompileResult sealed = compile(*graph, builtin_registry(), options, d);
  ASSERT_TRUE(sealed.plan) << d.to_string();
  EXPECT_EQ(state_of(*sealed.plan, "volume").first, NodeState::Kind::active);
  EXPECT_EQ(state_of(*sealed.plan, "ibl").first, NodeState::Kind::active);
  EXPECT_EQ(lookup_passes(*sealed.plan), 1);

  options.scene.irradiance_volumes = 0;
  CompileResult dark = compile(*graph, builtin_registry(), options, d);
  ASSERT_TRUE(dark.plan) << d.to_string();
  EXPECT_EQ(state_of(*dark.plan, "ibl").first, NodeState::Kind::bypassed);
}

}  // namespace
}  // namespace lg::test
