// The glTF metal-rough material through the G-buffer and lighting, on the assets of
// scripts/make-test-gltf (examples/gltf/) rendered at 96x96 with validation on. Each test fails
// without the feature it names: the normal map (and generated tangents, and the screen-space
// frame when a mesh has none), the MASK alpha test in the G-buffer and the shadow maps,
// double-sided materials, the metallic-roughness texture through texcoord set 1 and
// KHR_texture_transform, vertex colours,
// the occlusion texture, which must darken image-based light only, and BLEND materials, which
// the G-buffer skips and scene.forward_transparent composites back to front.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <iostream>
#include <map>
#include <string>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/common/gbuffer_normal.h"
#include "runtime/scene/mesh_import.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{96, 96};

World asset(const std::string& name) {
  World world;
  import_gltf(world, std::string(LUMAGRAPH_SOURCE_DIR "/examples/gltf/").append(name));
  return world;
}

// What a test frame runs: the G-buffer and direct light; with image-based light as well, the
// image-based light of a procedural sky (without the multi-bounce fit, which would brighten
// occlusion by the albedo); with transparency also scene.forward_transparent ("glass") over it.
enum class Lighting { direct, image_based, transparent };

Graph graph(Lighting lighting) {
  Diagnostics d("material-render-test.json");
  const std::string ibl_nodes = R"(
      { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "light", "type": "lighting.deferred" },
      { "id": "sky", "type": "env.sky" }, { "id": "sh", "type": "env.sh_project" },
      { "id": "specular", "type": "env.specular_prefilter" }, { "id": "dfg", "type": "env.brdf_lut" },
      { "id": "ibl", "type": "lighting.ibl", "params": { "multi_bounce": false } })";
  const std::string ibl_links = R"(
      { "from": "gbuf.gbuffer", "to": "light.gbuffer" }, { "from": "gbuf.gbuffer", "to": "ibl.gbuffer" },
      { "from": "light.color", "to": "ibl.direct" }, { "from": "sky.cube", "to": "sh.env" },
      { "from": "sky.cube", "to": "specular.env" }, { "from": "sh.sh", "to": "ibl.sh" },
      { "from": "specular.specular", "to": "ibl.specular" }, { "from": "dfg.lut", "to": "ibl.brdf_lut" })";
  std::string text;
  if (lighting == Lighting::direct)
    text = R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "light", "type": "lighting.deferred" } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "light.gbuffer" } ],
    "outputs": [ "light.color" ] })";
  else if (lighting == Lighting::image_based)
    text = R"({ "format": "lumagraph/1", "nodes": [)" + ibl_nodes + R"( ], "links": [)" + ibl_links +
           R"( ], "outputs": [ "ibl.color" ] })";
  else
    text = R"({ "format": "lumagraph/1", "nodes": [)" + ibl_nodes +
           R"(, { "id": "glass", "type": "scene.forward_transparent" } ], "links": [)" + ibl_links + R"(,
      { "from": "ibl.color", "to": "glass.color" }, { "from": "gbuf.gbuffer", "to": "glass.gbuffer" },
      { "from": "sh.sh", "to": "glass.sh" }, { "from": "specular.specular", "to": "glass.specular" },
      { "from": "dfg.lut", "to": "glass.brdf_lut" } ], "outputs": [ "glass.color", "ibl.color" ] })";
  std::optional<Graph> g = parse_graph_text(text, d);
  if (!g) throw std::runtime_error(d.to_string());
  return std::move(*g);
}

// One frame of `world`; the images are read back by name afterwards.
class Frame {
 public:
  explicit Frame(const World& world, Lighting lighting = Lighting::direct) : renderer_(options()) {
    renderer_.set_graph(graph(lighting));
    renderer_.render(world, kFrame);
    auto messages = renderer_.context().take_validation_messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  }
  // Float RGBA of pixel (x, y) of a resource ("gbuf.gbuffer.normal", "light.color"...).
  glm::vec4 at(const std::string& resource, int x, int y) {
    auto found = images_.find(resource);
    if (found == images_.end()) found = images_.emplace(resource, renderer_.executor().read_image(resource)).first;
    const size_t i = (size_t(y) * kFrame.width + size_t(x)) * 4;
    const auto& v = found->second;
    return {v[i], v[i + 1], v[i + 2], v[i + 3]};
  }
  glm::vec3 normal(int x, int y) {
    const glm::vec4 stored = at("gbuf.gbuffer.normal", x, y);
    return glm::vec3(decode_gbuffer_normal(&stored.x));
  }

 private:
  static RendererOptions options() {
    RendererOptions o;
    o.device.validation = true;
    o.alias = false;  // intermediate images are read back after the frame
    return o;
  }
  Renderer renderer_;
  std::map<std::string, std::vector<float>> images_;
};

// Also prints the largest difference, so that the margin under each tolerance is on record.
void expect_near(glm::vec3 a, glm::vec3 b, float tolerance, const std::string& what) {
  float largest = 0.0f;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(a[c], b[c], tolerance) << what << " component " << c;
    largest = std::max(largest, std::abs(a[c] - b[c]));
  }
  std::cout << what << ": largest difference " << largest << " (tolerance " << tolerance << ")\n";
}

// The plane spans pixels 10 to 85 of the 96x96 frame (2 m at 3 m with a vertical field of
// 0.8 rad); these lie well inside it, on its left and right halves, and in its middle.
constexpr int kLeft = 25, kRight = 71, kMiddle = 48;

// The normal texture holds (sin 30, 0, cos 30) in tangent space, the tangent along +X. Its
// 8-bit texel and the G-buffer's 10-bit normal put the stored normal within 0.006 of it; 0.01.
TEST(MaterialRender, NormalMapTiltsTheStoredNormal) {
  const glm::vec3 want(0.5f, 0.0f, std::sqrt(3.0f) / 2.0f);
  World world = asset("normal-mapped-plane.gltf");
  Frame generated(world);  // tangents generated on import
  for (int x : {kLeft, kMiddle, kRight}) expect_near(generated.normal(x, kMiddle), want, 0.01f, "generated tangents");
  world.edit_mesh(0).tangents.clear();  // the G-buffer's own frame from screen-space derivatives
  Frame derived(world);
  for (int x : {kLeft, kMiddle, kRight}) expect_near(derived.normal(x, kMiddle), want, 0.01f, "derived frame");
}

// The lit plane must match a plane without a normal map whose geometry is tilted the same 30
// degrees about its centre: at the centre both have the same point, normal, view and light, so
// their direct light agrees up to the normal map's 8-bit quantisation (under 0.004 rad: under
// 0.3% of n.l = 0.866, more with the specular lobe): 1%. Head-on, untilted, it would be 15% off.
TEST(MaterialRender, NormalMappedLightingMatchesTiltedGeometry) {
  World mapped = asset("normal-mapped-plane.gltf");
  World tilted = asset("normal-mapped-plane.gltf");
  tilted.edit_material(0).normal_texture.texture = -1;
  tilted.each<MeshRenderer, Transform>([](Entity, MeshRenderer&, Transform& t) {
    t.rotation = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0));  // +Z turns toward +X
  });
  Frame a(mapped), b(tilted);
  for (int y : {kMiddle - 1, kMiddle})
    for (int x : {kMiddle - 1, kMiddle}) {
      const glm::vec3 lit_mapped(a.at("light.color", x, y)), lit_tilted(b.at("light.color", x, y));
      ASSERT_GT(lit_tilted.g, 0.1f);
      expect_near(lit_mapped / lit_tilted, glm::vec3(1.0f), 0.01f, "mapped / tilted at the centre");
    }
}

// The quad's texture is transparent over uv 0.25-0.75 (nearest filtering): through the hole the
// G-buffer holds the red wall 1 m behind, around it the green quad. 8-bit sRGB albedo: 0.01.
TEST(MaterialRender, MaskCutsAHoleThroughToWhatIsBehind) {
  Frame f(asset("cut-out-quad.gltf"));
  const glm::vec3 wall(0.9f, 0.1f, 0.1f), quad(0.2f, 0.9f, 0.2f);
  expect_near(glm::vec3(f.at("gbuf.gbuffer.albedo", kMiddle, kMiddle)), wall, 0.01f, "through the hole");
  expect_near(glm::vec3(f.at("gbuf.gbuffer.albedo", 14, kMiddle)), quad, 0.01f, "the quad's opaque rim");
  // Reversed Z: the wall, farther, has the smaller depth.
  EXPECT_LT(f.at("gbuf.gbuffer.depth", kMiddle, kMiddle).r, f.at("gbuf.gbuffer.depth", 14, kMiddle).r);
}

// The cut-out quad lit by one light: its sun, or (sun removed) a spot, a point or a sphere
// light 2.5 m before the quad on the camera's axis, aiming down -Z.
enum class Light { sun, spot, point, sphere };

World cut_out_lit_by(Light light, bool shadows) {
  World world = asset("cut-out-quad.gltf");
  std::vector<Entity> suns;
  world.each<DirectionalLight>([&](Entity e, DirectionalLight& l) {
    l.casts_shadows = shadows;
    suns.push_back(e);
  });
  if (light == Light::sun) return world;
  for (Entity e : suns) world.remove<DirectionalLight>(e);
  Entity e = world.create("light");
  world.add(e, Transform{.position = {0.0f, 0.0f, 2.5f}});
  if (light == Light::spot) world.add(e, SpotLight{.intensity = 10.0f, .casts_shadows = shadows});
  if (light == Light::point) world.add(e, PointLight{.intensity = 10.0f, .casts_shadows = shadows});
  if (light == Light::sphere) world.add(e, SphereLight{.intensity = 300.0f, .casts_shadows = shadows});
  return world;
}

// Light passes the hole in the shadow maps as it does in the G-buffer: the wall seen through
// the middle of the hole is lit as brightly as with the light's shadows off (the same shading;
// half floats, 1e-3 relative), though it lies well inside the quad's shadow (on the wall the
// light through the hole spans |x| < 0.5 for the sun, < 0.7 for the lights at 2.5 m; the
// camera sees the wall through the hole out to |x| < 0.667). The sun's shadow of the quad's
// opaque rim, seen through the hole at pixel 64 (x = 0.58 m on the wall), stays dark.
TEST(MaterialRender, MaskLetsLightThroughTheShadowMaps) {
  for (Light light : {Light::sun, Light::spot, Light::point, Light::sphere}) {
    SCOPED_TRACE("light " + std::to_string(int(light)));
    Frame shadowed(cut_out_lit_by(light, true)), open(cut_out_lit_by(light, false));
    const glm::vec3 through(shadowed.at("light.color", kMiddle, kMiddle)),
        unshadowed(open.at("light.color", kMiddle, kMiddle));
    ASSERT_GT(unshadowed.r, 0.05f);
    expect_near(through / unshadowed, glm::vec3(1.0f), 1e-3f, "lit through the hole / unshadowed");
    if (light == Light::sun) {
      EXPECT_LT(shadowed.at("light.color", 64, kMiddle).r, 0.01f * open.at("light.color", 64, kMiddle).r)
          << "the rim's shadow seen through the hole";
    }
  }
}

// Turned to show its back, the double-sided quad still draws with cull_backfaces on (the
// default), its normal flipped toward the camera; single-sided, it is culled and the wall shows.
TEST(MaterialRender, DoubleSidedDrawsTheBackWithAFlippedNormal) {
  World world = asset("cut-out-quad.gltf");
  world.each<MeshRenderer, Transform>([](Entity, MeshRenderer& m, Transform& t) {
    if (m.material == 0) t.rotation = glm::angleAxis(glm::radians(180.0f), glm::vec3(0, 1, 0));
  });
  Frame both(world);
  expect_near(glm::vec3(both.at("gbuf.gbuffer.albedo", 14, kMiddle)), {0.2f, 0.9f, 0.2f}, 0.01f, "back of the quad");
  expect_near(both.normal(14, kMiddle), {0, 0, 1}, 0.01f, "flipped normal");
  world.edit_material(0).double_sided = false;
  Frame culled(world);
  expect_near(glm::vec3(culled.at("gbuf.gbuffer.albedo", 14, kMiddle)), {0.9f, 0.1f, 0.1f}, 0.01f, "culled");
}

// The ORM texture through set 1 and its transform: left half roughness 230/255, metal 0,
// occlusion 64/255; right half roughness 51/255, metal 1, occlusion 1 (texels, nearest). rg8 and
// the alpha of rgba8 store these within half a step: 0.003. Without the transform, or reading
// set 0, the halves swap. Vertex colours halve the red of the base colour (0.9, 0.7, 0.3):
// 8-bit sRGB storage, 0.01.
TEST(MaterialRender, MetallicRoughnessOcclusionTexcoordSetTransformAndVertexColour) {
  Frame f(asset("metal-rough-plane.gltf"));
  const glm::vec4 left = f.at("gbuf.gbuffer.material", kLeft, kMiddle),
                  right = f.at("gbuf.gbuffer.material", kRight, kMiddle);
  EXPECT_NEAR(left.r, 230.0f / 255.0f, 0.003f);
  EXPECT_NEAR(left.g, 0.0f, 0.003f);
  EXPECT_NEAR(right.r, 51.0f / 255.0f, 0.003f);
  EXPECT_NEAR(right.g, 1.0f, 0.003f);
  EXPECT_NEAR(f.at("gbuf.gbuffer.albedo", kLeft, kMiddle).a, 64.0f / 255.0f, 0.003f);
  EXPECT_NEAR(f.at("gbuf.gbuffer.albedo", kRight, kMiddle).a, 1.0f, 0.003f);
  expect_near(glm::vec3(f.at("gbuf.gbuffer.albedo", kRight, kMiddle)), {0.9f * 128.0f / 255.0f, 0.7f, 0.3f}, 0.01f,
              "base colour x vertex colour");
}

// Occlusion darkens the image-based light (ibl.color minus the direct light it adds) and leaves
// the direct light as it was. On the left half (occlusion 64/255, a rough dielectric) the
// diffuse IBL scales by 0.251 and the small specular by Lagarde's factor, which at roughness 0.9
// facing the camera is the same 0.251. Both images are half floats near 0.5 (steps of 0.0005)
// around an ambient term of about 0.06, so the ratio is known to about 0.015: 0.251 +- 0.02.
// The direct light agrees to 1e-6.
TEST(MaterialRender, OcclusionTextureDarkensOnlyImageBasedLight) {
  World occluded = asset("metal-rough-plane.gltf");
  World open = asset("metal-rough-plane.gltf");
  open.edit_material(0).occlusion_texture.texture = -1;
  for (World* w : {&occluded, &open}) w->add<EnvironmentLight>(w->create("sky"));  // the procedural sky
  Frame a(occluded, Lighting::image_based), b(open, Lighting::image_based);
  const glm::vec3 direct_a(a.at("light.color", kLeft, kMiddle)), direct_b(b.at("light.color", kLeft, kMiddle));
  expect_near(direct_a, direct_b, 1e-6f, "direct light");
  const glm::vec3 ambient_a = glm::vec3(a.at("ibl.color", kLeft, kMiddle)) - direct_a;
  const glm::vec3 ambient_b = glm::vec3(b.at("ibl.color", kLeft, kMiddle)) - direct_b;
  ASSERT_GT(ambient_b.g, 0.01f);
  const glm::vec3 ratio = ambient_a / ambient_b;
  std::cout << "ambient with / without occlusion: " << ratio.r << " " << ratio.g << " " << ratio.b << "\n";
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 64.0f / 255.0f, 0.02f) << "channel " << c;
  // The right half has occlusion 1: unchanged.
  expect_near(glm::vec3(a.at("ibl.color", kRight, kMiddle)), glm::vec3(b.at("ibl.color", kRight, kMiddle)), 1e-6f,
              "no occlusion");
}

// glass-panes.gltf: the red pane (alpha 0.5) covers pixels 16 to 53 of row kMiddle, the blue one
// (alpha 0.5, 0.5 m nearer) 41 to 86; kLeft sees the red alone, kMiddle both, kRight the blue.
// The world has the procedural sky, and its sun casts no shadows: lighting.deferred draws BLEND
// draws into its shadow map while scene.forward_transparent reads none, so an opaque pane and
// the same pane drawn as glass are lit alike only without them.
World glass_world() {
  World world = asset("glass-panes.gltf");
  world.add<EnvironmentLight>(world.create("sky"));
  world.each<DirectionalLight>([](Entity, DirectionalLight& l) { l.casts_shadows = false; });
  return world;
}

// The G-buffer skips BLEND draws: behind the red pane it holds the white wall, at the wall's
// depth (that of a pixel where only the wall shows). 8-bit sRGB albedo: 0.01.
TEST(MaterialRender, GBufferSkipsBlendDraws) {
  Frame f(glass_world());
  expect_near(glm::vec3(f.at("gbuf.gbuffer.albedo", kLeft, kMiddle)), glm::vec3(0.9f), 0.01f, "behind the glass");
  EXPECT_EQ(f.at("gbuf.gbuffer.depth", kLeft, kMiddle).r, f.at("gbuf.gbuffer.depth", kLeft, 5).r);
}

// The lit glass, as the same pane made opaque is lit by the deferred and image-based passes
// (ibl.color of that frame); its "over" composite with alpha a onto the lit wall behind.
glm::vec3 over(float alpha, glm::vec3 glass, glm::vec3 behind) {
  return alpha * glass + (1.0f - alpha) * behind;
}

// The composite differs from the analytic mix by what the G-buffer path quantises in the opaque
// pane (8-bit sRGB albedo: half a step of the 0.1 channel is 1.3% of it; 8-bit roughness) and
// by half floats (0.05%): within 1.5% of the expected value plus 0.002 for the darkest channels.
void expect_composite(glm::vec3 got, glm::vec3 want, const std::string& what) {
  float largest = 0.0f;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(got[c], want[c], 0.015f * want[c] + 0.002f) << what << " component " << c;
    largest = std::max(largest, std::abs(got[c] - want[c]) / want[c]);
  }
  std::cout << what << ": got " << got.r << " " << got.g << " " << got.b << ", want " << want.r << " " << want.g << " "
            << want.b << ", largest relative difference " << largest << "\n";
}

// Behind the red pane alone the output is 0.5 x the lit glass + 0.5 x the lit wall (ibl.color,
// which the glass no longer hides). Without the forward pass it would be the wall alone.
TEST(MaterialRender, BlendPaneCompositesOverTheLitWall) {
  World glass = glass_world(), opaque = glass_world();
  opaque.edit_material(0).alpha_mode = AlphaMode::opaque;
  Frame f(glass, Lighting::transparent), lit(opaque, Lighting::transparent);
  const glm::vec3 wall(f.at("ibl.color", kLeft, kMiddle)), pane(lit.at("ibl.color", kLeft, kMiddle));
  ASSERT_GT(pane.r, 2.0f * pane.g);  // the opaque pane is red, and what is behind it white
  expect_composite(glm::vec3(f.at("glass.color", kLeft, kMiddle)), over(0.5f, pane, wall), "red pane over the wall");
  // Where no glass is, the output is its input.
  expect_near(glm::vec3(f.at("glass.color", kLeft, 5)), glm::vec3(f.at("ibl.color", kLeft, 5)), 0.0f, "no glass");
}

// Where the panes overlap, the blue one in front: 0.5 x blue + 0.5 x (0.5 x red + 0.5 x wall),
// whichever of the two the scene draws first (the second world swaps their meshes and
// materials, so its draw order is reversed). Drawn in the scene's order without sorting, one of
// the two would put red over blue.
TEST(MaterialRender, OverlappingPanesCompositeBackToFrontInAnyDrawOrder) {
  World red_opaque = glass_world(), blue_opaque = glass_world();
  red_opaque.edit_material(0).alpha_mode = AlphaMode::opaque;
  blue_opaque.edit_material(1).alpha_mode = AlphaMode::opaque;
  Frame lit_red(red_opaque, Lighting::transparent), lit_blue(blue_opaque, Lighting::transparent);
  const glm::vec3 red(lit_red.at("ibl.color", kMiddle, kMiddle)), blue(lit_blue.at("ibl.color", kMiddle, kMiddle));

  World listed = glass_world(), reversed = glass_world();
  MeshRenderer* panes[2] = {};
  reversed.each<MeshRenderer>([&](Entity, MeshRenderer& m) {
    if (m.material == 0 || m.material == 1) panes[m.material] = &m;
  });
  ASSERT_TRUE(panes[0] && panes[1]);
  std::swap(*panes[0], *panes[1]);
  for (World* world : {&listed, &reversed}) {
    Frame f(*world, Lighting::transparent);
    const glm::vec3 wall(f.at("ibl.color", kMiddle, kMiddle));
    expect_composite(glm::vec3(f.at("glass.color", kMiddle, kMiddle)), over(0.5f, blue, over(0.5f, red, wall)),
                     world == &listed ? "overlap, drawn as listed" : "overlap, drawn in reverse");
  }
}

}  // namespace
}  // namespace lg::test
