// glTF 2.0 import of tests/scene/data/scene.gltf (buffer and image as data: URIs) and its .glb
// twin, and of broken variants made here: each must give a SceneError naming the file and the
// problem, never a crash. Tolerance on imported numbers: 1e-5 (float from JSON doubles).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "import_test_support.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_import.h"
#include "runtime/scene/mesh_tools.h"

namespace lg {
namespace {

using test::error_of;
using test::fixture;
using test::replaced;
using test::write_variant;

const MeshData* mesh_named(const World& w, const std::string& name) {
  for (const auto& m : w.meshes())
    if (m->name == name) return m.get();
  return nullptr;
}

void expect_near(glm::vec3 a, glm::vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

void check_fixture_world(const World& w) {
  ASSERT_EQ(w.meshes().size(), 2u);
  ASSERT_EQ(w.materials().size(), 1u);
  ASSERT_EQ(w.textures().size(), 1u);
  EXPECT_EQ(w.entity_count(), 6u);

  const MeshData* quad = mesh_named(w, "quad");
  ASSERT_NE(quad, nullptr);
  EXPECT_EQ(quad->positions.size(), 4u);
  EXPECT_EQ(quad->indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(quad->normals.size(), 4u);  // generated: the quad faces +Z
  for (const auto& n : quad->normals) expect_near(n, {0, 0, 1});
  ASSERT_EQ(quad->uvs.size(), 4u);
  EXPECT_EQ(quad->uvs[0], glm::vec2(0, 1));
  const MeshData* tri = mesh_named(w, "tri");
  ASSERT_NE(tri, nullptr);
  EXPECT_EQ(tri->indices, (std::vector<uint32_t>{0, 1, 2}));  // from unsigned bytes
  EXPECT_TRUE(tri->uvs.empty());

  const PbrMaterial& m = w.materials()[0];
  EXPECT_EQ(m.name, "red");
  EXPECT_EQ(m.base_color, glm::vec4(1, 0.5f, 0.25f, 1));
  EXPECT_FLOAT_EQ(m.metalness, 0.5f);
  EXPECT_FLOAT_EQ(m.roughness, 0.25f);
  expect_near(m.emissive, {0.1f, 0.2f, 0.3f});
  ASSERT_EQ(m.base_color_texture.texture, 0);
  const TextureData& t = *w.textures()[0];
  EXPECT_EQ(t.width, 2u);
  EXPECT_EQ(t.height, 1u);
  EXPECT_EQ(t.rgba8, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));  // RGB PNG, alpha added

  SceneView v = make_scene_view(w, 1.5f);
  // The quad's corner (0.5, 0.5, 0): scaled by 2, turned 90 degrees about Y, moved by the
  // root's (1, 2, 3): (1, 3, 2).
  const DrawItem* quad_draw = nullptr;
  for (const auto& d : v.draws)
    if (v.mesh_of(d).name == "quad") quad_draw = &d;
  ASSERT_NE(quad_draw, nullptr);
  expect_near(glm::vec3(quad_draw->world * glm::vec4(0.5f, 0.5f, 0.0f, 1.0f)), {1, 3, 2});
  EXPECT_EQ(quad_draw->material, 0);
  for (const auto& d : v.draws)
    if (&d != quad_draw) expect_near(glm::vec3(d.world[3]), {1, 2, 2});  // the matrix node

  EXPECT_NEAR(v.camera.vertical_fov, 0.6f, 1e-6f);
  EXPECT_NEAR(v.camera.near_plane, 0.1f, 1e-6f);
  expect_near(v.camera.position, {0, 1, 5});
  ASSERT_EQ(v.directional_lights.size(), 1u);
  expect_near(v.directional_lights[0].direction, glm::normalize(glm::vec3(0, -1, -1)));
  expect_near(v.directional_lights[0].irradiance, {2.0f, 1.8f, 1.6f});
  ASSERT_EQ(v.point_lights.size(), 1u);
  expect_near(v.point_lights[0].position, {0, 3, 0});
  expect_near(v.point_lights[0].intensity, glm::vec3(5.0f));
  EXPECT_FLOAT_EQ(v.point_lights[0].range, 10.0f);
}

TEST(GltfImport, TextFileWithDataUris) {
  World w;
  std::vector<Entity> roots = import_gltf(w, fixture("scene.gltf"));
  EXPECT_EQ(roots.size(), 4u);
  check_fixture_world(w);
}

TEST(GltfImport, BinaryFile) {
  World w;
  import_gltf(w, fixture("scene.glb"));
  check_fixture_world(w);
}

TEST(GltfImport, ParentsRootNodesUnderTheGivenEntity) {
  World w;
  Entity holder = w.create();
  w.add<Transform>(holder, {{0, 10, 0}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f), {}});
  for (Entity root : import_gltf(w, fixture("scene.gltf"), holder)) EXPECT_EQ(w.get<Transform>(root).parent, holder);
  EXPECT_NEAR(make_scene_view(w, 1.0f).camera.position.y, 11.0f, 1e-5f);
}

// The fixture's point light made a KHR_lights_punctual spot with `cone`, its node turned to aim
// down (-90 degrees about X takes -Z to -Y).
std::string spot_variant(const std::string& name, const std::string& cone) {
  std::string text = replaced(test::read_bytes(fixture("scene.gltf")), R"({"type": "point", "intensity": 5.0,)",
                              R"({"type": "spot", "spot": )" + cone + R"(, "intensity": 5.0,)");
  text = replaced(text, R"({"name": "lamp", "translation": [0, 3, 0],)",
                  R"({"name": "lamp", "translation": [0, 3, 0], "rotation": [-0.70710678, 0, 0, 0.70710678],)");
  return write_variant(name + ".gltf", text);
}

TEST(GltfImport, SpotLightKeepsItsCone) {
  World w;
  import_gltf(w, spot_variant("spot", R"({"innerConeAngle": 0.3, "outerConeAngle": 0.6})"));
  SceneView v = make_scene_view(w, 1.0f);
  EXPECT_TRUE(v.point_lights.empty());
  ASSERT_EQ(v.spot_lights.size(), 1u);
  const SpotLightData& spot = v.spot_lights[0];
  expect_near(spot.position, {0, 3, 0});
  expect_near(spot.direction, {0, -1, 0});
  expect_near(spot.intensity, glm::vec3(5.0f));
  EXPECT_FLOAT_EQ(spot.range, 10.0f);
  EXPECT_FLOAT_EQ(spot.inner_cone_angle, 0.3f);
  EXPECT_FLOAT_EQ(spot.outer_cone_angle, 0.6f);
  EXPECT_TRUE(v.summary().has(SceneFeature::spot_lights));
}

TEST(GltfImport, SpotLightWithoutAnglesTakesTheSpecsDefaults) {
  World w;
  import_gltf(w, spot_variant("spot_defaults", "{}"));
  const SceneView v = make_scene_view(w, 1.0f);
  ASSERT_EQ(v.spot_lights.size(), 1u);
  EXPECT_FLOAT_EQ(v.spot_lights[0].inner_cone_angle, 0.0f);
  EXPECT_FLOAT_EQ(v.spot_lights[0].outer_cone_angle, 0.7853982f);  // pi / 4
}

TEST(GltfImport, SpotLightConeOutsideTheSpecIsAnError) {
  for (const char* cone :
       {R"({"innerConeAngle": 0.6, "outerConeAngle": 0.6})", R"({"innerConeAngle": 0.2, "outerConeAngle": 1.7})",
        R"({"innerConeAngle": -0.1, "outerConeAngle": 0.5})"}) {
    std::string path = spot_variant("bad_spot", cone);
    World w;
    std::string message = error_of([&] { import_gltf(w, path); });
    EXPECT_EQ(message.rfind(path + ": error: light 1 (a spot) has cone angles", 0), 0u) << message;
    EXPECT_NE(message.find("expected 0 <= innerConeAngle < outerConeAngle <= pi/2"), std::string::npos) << message;
  }
}

struct BrokenGltf {
  const char* name;
  const char* from;
  const char* to;
  const char* message;  // a part of the error
};

void PrintTo(const BrokenGltf& c, std::ostream* out) {
  *out << c.name;
}

class GltfBroken : public testing::TestWithParam<BrokenGltf> {};

TEST_P(GltfBroken, GivesAClearError) {
  const BrokenGltf& c = GetParam();
  std::string path =
      write_variant(std::string(c.name) + ".gltf", replaced(test::read_bytes(fixture("scene.gltf")), c.from, c.to));
  World w;
  std::string message = error_of([&] { import_gltf(w, path); });
  EXPECT_EQ(message.rfind(path + ": error: ", 0), 0u) << message;
  EXPECT_NE(message.find(c.message), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GltfBroken,
    testing::Values(
        BrokenGltf{"accessor_past_view", R"("count": 4, "type": "VEC3")", R"("count": 400, "type": "VEC3")",
                   "mesh 0 primitive 0 POSITION (accessor 0): 400 elements run past the end of buffer view 0"},
        BrokenGltf{"index_out_of_range", R"("indices": 3)", R"("indices": 6)",
                   "mesh 1 primitive 0: index 7 is out of range (3 vertices)"},
        BrokenGltf{"no_such_accessor", R"("indices": 3)", R"("indices": 60)", "accessor out of bounds"},
        BrokenGltf{"view_past_buffer", R"("byteOffset": 100, "byteLength": 36)",
                   R"("byteOffset": 120, "byteLength": 36)", "buffer view 4 runs past the end of buffer 0 (136 bytes)"},
        BrokenGltf{"wrong_type", R"("componentType": 5126, "count": 3, "type": "VEC3"})",
                   R"("componentType": 5126, "count": 3, "type": "VEC2"})", "NORMAL (accessor 4) has the wrong type"},
        BrokenGltf{"no_such_child", R"("children": [1, 2])", R"("children": [1, 99])", "node 99 does not exist"},
        BrokenGltf{"cycle", R"("children": [1, 2])", R"("children": [1, 0])", "node 0 is its own ancestor"},
        BrokenGltf{"no_such_material", R"("material": 0)", R"("material": 5)", "material 5 does not exist"},
        BrokenGltf{"no_such_light", R"({"light": 1})", R"({"light": 9})", "light 9 does not exist"},
        BrokenGltf{"missing_buffer", R"("uri": "data:application/octet-stream;base64,)",
                   R"("uri": "missing.bin", "x": ")", "missing.bin"},
        BrokenGltf{"buffer_outside_folder", R"("uri": "data:application/octet-stream;base64,)",
                   R"("uri": "../CMakeCache.txt", "x": ")", "is outside the folder of the glTF file"},
        BrokenGltf{"buffer_is_a_folder", R"("uri": "data:application/octet-stream;base64,)",
                   R"("uri": ".", "x": ")", "is not a file"},
        // Found by the gltf fuzzer: the NUL ends the path at the folder.
        BrokenGltf{"buffer_uri_starts_with_nul", R"("uri": "data:application/octet-stream;base64,)",
                   R"("uri": "\u0000.bin", "x": ")", "is not a file"},
        BrokenGltf{"missing_image", R"("uri": "data:image/png;base64,)", R"("uri": "missing.png", "x": ")",
                   "missing.png"},
        BrokenGltf{"corrupt_image", R"("uri": "data:image/png;base64,)",
                   R"("uri": "data:image/png;base64,AAAA", "x": ")", "cannot decode image data for image[0]"},
        BrokenGltf{"not_json", R"("asset")", R"(asset)", "not a valid glTF file"}),
    [](const testing::TestParamInfo<BrokenGltf>& info) { return std::string(info.param.name); });

// Every prefix of the files at a stride, and single-byte corruptions: an error or a world,
// never a crash or an exception of another type.
TEST(GltfImport, TruncatedAndCorruptedFilesNeverCrash) {
  for (const char* name : {"scene.gltf", "scene.glb"}) {
    std::string bytes = test::read_bytes(fixture(name));
    std::string ext = std::string(name).substr(std::string(name).find('.'));
    for (size_t length = 0; length < bytes.size(); length += 13) {
      std::string path = write_variant("truncated" + ext, bytes.substr(0, length));
      World w;
      EXPECT_THROW(import_gltf(w, path), SceneError) << name << " cut at " << length;
    }
    for (size_t at = 0; at < bytes.size(); at += 11) {
      std::string flipped = bytes;
      flipped[at] = static_cast<char>(flipped[at] ^ 0x5a);
      std::string path = write_variant("flipped" + ext, flipped);
      World w;
      try {
        import_gltf(w, path);
        for (const auto& m : w.meshes()) EXPECT_EQ(mesh_problem(*m), "");
      } catch (const SceneError&) {
      }
    }
  }
}

TEST(GltfImport, MissingFileIsNamed) {
  World w;
  std::string message = error_of([&] { import_gltf(w, fixture("nothing.gltf")); });
  EXPECT_EQ(message, fixture("nothing.gltf") + ": error: the file does not exist");
}

}  // namespace
}  // namespace lg
