// The raster capture's light from gi.irradiance_volume (its `probes` output linked to
// gi.reflection_capture's `probe_volume`): a wall lit by nothing but the volume, seen by a probe's
// -Z face, is black without the link and, with it, what lighting.ibl would make of the volume's
// irradiance there: albedo (1 - specular albedo) E / pi per texel, E from the CPU lookup of the
// very probes the kernel baked (probe_lookup.h), the specular albedo from the tabulated DFG
// reference (brdf_albedo.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "nodes/env/common/cube_map.h"
#include "nodes/gi/irradiance_volume/probe_snapshot.h"
#include "nodes/gi/probes/probe_file.h"
#include "nodes/gi/probes/probe_lookup.h"
#include "nodes/gi/reflection_capture/captured_cube_source.h"
#include "runtime/scene/scene_file.h"
#include "tests/gi/plan_kernel.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{64, 48};
constexpr uint32_t kFace = 16;
constexpr int kMinusZ = 5;  // cube_map.h's face order
constexpr double kAlbedo = 0.8, kRoughness = 1.0, kF0 = 0.04;
constexpr double kWallZ = -1.95;  // the wall's face toward the probe
const glm::dvec3 kProbe{0.0, 1.0, 0.0};

// One white wall 20 m wide 1.95 m in front of the probe, filling its -Z face; no lights, so the
// wall's only light in the capture (intensity 0: no environment either) is the volume's, whose
// probes the sky lights. The volume's probes stand clear of the wall (z from -1.8 to 0).
constexpr const char* kWorld = R"({
  "format": "lumagraph-world/1",
  "name": "volume-lit wall",
  "materials": { "wall": {"base_color": [0.8, 0.8, 0.8], "roughness": 1.0} },
  "environment": {"intensity": 1},
  "entities": [
    {"name": "wall", "transform": {"position": [0, 1, -2]}, "shape": {"type": "box", "size": [20, 20, 0.1]},
     "material": "wall"},
    {"name": "volume", "transform": {"position": [0, 1, -0.9]}, "irradiance_volume": {"size": [4, 2, 1.8], "probes": [3, 3, 3]}},
    {"name": "probe", "transform": {"position": [0, 1, 0]}, "reflection_probe": {"extent": [3, 3, 3]}},
    {"name": "camera", "transform": {"position": [0, 1, 3], "look_at": [0, 1, 0]}, "camera": {"vertical_fov": 60}}
  ]
})";

std::string graph(bool linked) {
  return std::string(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "sky", "type": "env.sky", "params": { "face_size": 16 } },
      { "id": "sh", "type": "env.sh_project", "params": { "order": 2, "window": "none", "convolve_cosine": true } },
      { "id": "specular", "type": "env.specular_prefilter", "params": { "face_size": 16, "mips": 3, "samples": 16 } },
      { "id": "dfg", "type": "env.brdf_lut", "params": { "size": 32, "samples": 64 } },
      { "id": "volume", "type": "gi.irradiance_volume", "params": { "rays": 128, "bounces": 2 } },
      { "id": "probes", "type": "gi.reflection_capture",
        "params": { "capture": "raster", "face_size": 16, "mips": 1, "prefilter_samples": 1, "intensity": 0 } } ],
    "links": [
      { "from": "sky.cube", "to": "sh.env" },
      { "from": "sky.cube", "to": "specular.env" },
      { "from": "gbuf.gbuffer", "to": "volume.gbuffer" },
      { "from": "gbuf.gbuffer", "to": "probes.gbuffer" },
      { "from": "sh.sh", "to": "probes.sh" },
      { "from": "specular.specular", "to": "probes.specular" },
      { "from": "dfg.lut", "to": "probes.brdf_lut" })") +
         (linked ? R"(, { "from": "volume.probes", "to": "probes.probe_volume" })" : "") + R"( ],
    "outputs": [ "probes.reflections", "volume.irradiance" ] })";
}

Graph parse(bool linked) {
  Diagnostics d("capture-volume-test.json");
  std::optional<Graph> g = parse_graph_text(graph(linked), d);
  if (!g) throw std::runtime_error(d.to_string());
  return std::move(*g);
}

std::vector<float> minus_z_face(Renderer& renderer) {
  return kernel_of<CapturedCubeSource>(renderer, "probes")
      .read_captured_face(renderer.executor().submitter(), 0, kMinusZ);
}

// What the capture should hold at texel (i, j) of the -Z face: the wall point it sees lit by the
// volume as lighting.ibl lights it (the environment's share is 0 at intensity 0), green channel.
double expected_texel(std::span<const ProbeGrid> grids, uint32_t i, uint32_t j) {
  const glm::dvec3 d = cube_direction(kMinusZ, (i + 0.5) / kFace, (j + 0.5) / kFace);
  const glm::dvec3 p = kProbe + d * ((kWallZ - kProbe.z) / d.z);
  const glm::dvec3 n{0.0, 0.0, 1.0};
  const VolumeIrradiance e = lookup_volumes(grids, p, n, kProbe, ProbeLookupSettings{});  // the node's defaults
  const glm::dvec2 scale_bias = brdf_albedo_lookup(glm::dot(n, glm::normalize(kProbe - p)), kRoughness);
  const double specular_albedo =
      (kF0 * scale_bias.x + scale_bias.y) * specular_energy_scale(glm::dvec3(kF0), scale_bias).y;
  return kAlbedo * (1.0 - specular_albedo) * e.coverage * e.irradiance.y / std::numbers::pi;
}

TEST(CaptureVolume, TheVolumesLightReachesTheCapturedWall) {
  const World world = parse_scene_file(kWorld, "capture-volume-test.world.json");
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;
  Renderer renderer(options);  // one device for both graphs
  renderer.set_graph(parse(false));
  renderer.render(world, kFrame);
  expect_no_validation_messages(renderer.context());
  const std::vector<float> dark = minus_z_face(renderer);
  renderer.set_graph(parse(true));
  renderer.render(world, kFrame);
  expect_no_validation_messages(renderer.context());
  const std::vector<float> lit = minus_z_face(renderer);
  const std::vector<ProbeGrid> grids =
      probe_grids(kernel_of<ProbeSnapshotSource>(renderer, "volume").probe_snapshot().file);
  ASSERT_EQ(lit.size(), size_t(kFace) * kFace * 4);
  double dark_sum = 0.0, lit_sum = 0.0, expected_sum = 0.0, worst = 0.0;
  for (uint32_t j = 0; j < kFace; ++j)
    for (uint32_t i = 0; i < kFace; ++i) {
      const size_t t = (size_t(j) * kFace + i) * 4 + 1;
      ASSERT_TRUE(std::isfinite(lit[t]));
      const double expected = expected_texel(grids, i, j);
      dark_sum += dark[t];
      lit_sum += lit[t];
      expected_sum += expected;
      worst = std::max(worst, std::abs(lit[t] - expected) / expected);
    }
  const double texels = double(kFace) * kFace;
  std::printf("-Z face, green: unlinked %.5f, linked %.5f, expected %.5f W/(m^2 sr); worst texel off by %.2f%%\n",
              dark_sum / texels, lit_sum / texels, expected_sum / texels, 100.0 * worst);
  ASSERT_GT(expected_sum / texels, 0.01);  // the sky lights the volume's probes: there is light to find
  // Nothing but the volume lights the wall: black without the link (the clear value is the sky's
  // black at intensity 0, and no light reaches the wall).
  EXPECT_EQ(dark_sum, 0.0);
  // The mean within 2% of the CPU's (measured: 0.03%): the GPU looks the probes up in float with
  // the hardware's bilinear taps of the half-float atlas (lavapipe's filtering weights have 8
  // bits), env.brdf_lut's 32 x 32 table of 64 samples a texel against brdf_albedo.h's (the
  // specular albedo is about 5% of the light at roughness 1, so even a 10% error in it moves the
  // result 0.5%), and the face is half floats (0.05%). A volume read at the wrong place, with the
  // wrong normal or without the energy split is off by more: the irradiance varies by 40% over
  // the face.
  EXPECT_NEAR(lit_sum, expected_sum, 0.02 * expected_sum);
  // Texel by texel within 5% (measured: 0.08%): the same, without the mean's averaging.
  EXPECT_LT(worst, 0.05);
}

// Without an environment the capture needs no environment inputs, but the volume's light is split
// from the specular by the DFG table: linked without brdf_lut, the frame fails naming the node and
// the missing input, rather than reading the placeholder as a table.
TEST(CaptureVolume, AVolumeWithoutTheDfgTableIsRefusedByName) {
  std::string world_text = kWorld;
  const std::string environment = R"("environment": {"intensity": 1},)";
  world_text.erase(world_text.find(environment), environment.size());
  const World world = parse_scene_file(world_text, "capture-volume-test.world.json");
  Diagnostics d("capture-volume-test.json");
  std::optional<Graph> g = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "volume", "type": "gi.irradiance_volume", "params": { "rays": 16, "bounces": 1 } },
      { "id": "probes", "type": "gi.reflection_capture", "params": { "capture": "raster", "face_size": 4, "mips": 1 } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "volume.gbuffer" }, { "from": "gbuf.gbuffer", "to": "probes.gbuffer" },
               { "from": "volume.probes", "to": "probes.probe_volume" } ],
    "outputs": [ "probes.reflections" ] })",
                                            d);
  ASSERT_TRUE(g) << d.to_string();
  Renderer renderer;
  renderer.set_graph(std::move(*g));
  try {
    renderer.render(world, kFrame);
    FAIL() << "the frame ran without the DFG table";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("gi.reflection_capture 'probes': with 'probe_volume' linked the input "
                                         "'brdf_lut' must be linked too"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lg::test
