// Scene files: a file using every kind of entity loads into the expected world, and broken
// files report every error with its exact line, column and JSON pointer.
#include "runtime/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <iostream>

#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

// Scene text is "written" into tests/scene/data/ so that its relative paths find the fixtures.
std::string data_dir() {
  return std::string(LUMAGRAPH_SOURCE_DIR "/tests/scene/data");
}
std::string fake_path() {
  return std::string(LUMAGRAPH_SOURCE_DIR "/tests/scene/data/inline.json");
}

// The messages of parse_scene_file(text), "line:col: message (pointer)" without the file name.
std::vector<std::string> errors_of(const std::string& text) {
  try {
    parse_scene_file(text, fake_path());
  } catch (const SceneError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics().items()) {
      std::string s = d.to_string();
      EXPECT_EQ(s.rfind(fake_path() + ":", 0), 0u) << s;
      out.push_back(s.substr(fake_path().size() + 1));
    }
    return out;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

const char* every_kind = R"({
  "format": "lumagraph-world/1",
  "name": "every kind",
  "materials": {
    "red": {"base_color": [0.8, 0.1, 0.1], "roughness": 0.95},
    "gold": {"base_color": [1, 0.8, 0.3], "roughness": 0.3, "metalness": 1, "emissive": [0, 0, 0]}
  },
  "environment": {"intensity": 0.5},
  "post": {"exposure": -1},
  "entities": [
    {"name": "stage", "transform": {"position": [0, 1, 0], "rotation": [0, 90, 0]}},
    {"name": "cube", "parent": "stage", "model": "cube.obj", "material": "gold", "captured_by_probes": false},
    {"name": "gltf", "model": "scene.gltf", "transform": {"scale": 0.5}},
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "material": "red", "captured_by_probes": false},
    {"name": "floor", "shape": {"type": "quad", "size": [10, 10]}},
    {"name": "pill", "shape": {"type": "capsule", "length": 1, "radius": 0.2}},
    {"name": "box", "shape": {"type": "box", "size": [1, 2, 3]}},
    {"name": "bunny", "shape": {"type": "bunny"}},
    {"name": "sun", "transform": {"rotation": [0.0, 0.0, 0.0, 1.0]},
     "directional_light": {"color": [1, 1, 1], "irradiance": 3, "angular_radius": 0.27, "shadows": false}},
    {"name": "bulb", "point_light": {"intensity": 10, "range": 5}},
    {"name": "cone", "transform": {"position": [0, 3, 0], "look_at": [0, 0, 0]},
     "spot_light": {"color": [1, 0.5, 0.25], "intensity": 12, "range": 8, "inner_angle": 15, "outer_angle": 25,
                    "shadows": false}},
    {"name": "orb", "transform": {"position": [1, 2, 3]}, "sphere_light": {"radiance": 20, "radius": 0.1}},
    {"name": "tube", "tube_light": {"color": [0.5, 0.5, 1], "radiance": 8, "length": 2, "radius": 0.05}},
    {"name": "panel", "rect_light": {"radiance": 4, "width": 2, "height": 1, "two_sided": true, "shadows": false}},
    {"name": "volume", "irradiance_volume": {"size": [10, 4, 10], "probes": [8, 4, 8]}},
    {"name": "probe", "reflection_probe": {"radius": 3}},
    {"name": "eye", "transform": {"position": [0, 1.5, 6], "look_at": [0, 1, 0]},
     "camera": {"vertical_fov": 45, "near": 0.1, "aperture": 0.01, "focus_distance": 6}}
  ]
})";

TEST(SceneFile, EveryKindOfEntityLoads) {
  World w = parse_scene_file(every_kind, fake_path());
  EXPECT_EQ(w.name, "every kind");
  SceneView v = make_scene_view(w, 16.0f / 9.0f);
  SceneSummary s = v.summary();
  EXPECT_EQ(s.directional_lights, 2);  // the sun and the glTF file's
  EXPECT_EQ(s.point_lights, 2);        // the bulb and the glTF file's
  EXPECT_EQ(s.spot_lights, 1);
  EXPECT_TRUE(s.has(SceneFeature::spot_lights));
  ASSERT_EQ(v.spot_lights.size(), 1u);
  const SpotLightData& cone = v.spot_lights[0];
  EXPECT_NEAR(glm::distance(cone.position, glm::vec3(0, 3, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(cone.direction, glm::vec3(0, -1, 0)), 0.0f, 1e-5f);  // toward look_at
  EXPECT_EQ(cone.intensity, glm::vec3(12.0f, 6.0f, 3.0f));
  EXPECT_FLOAT_EQ(cone.range, 8.0f);
  EXPECT_NEAR(cone.inner_cone_angle, glm::radians(15.0f), 1e-6f);
  EXPECT_NEAR(cone.outer_cone_angle, glm::radians(25.0f), 1e-6f);
  EXPECT_FALSE(cone.casts_shadows);
  EXPECT_EQ(s.sphere_lights, 1);
  EXPECT_EQ(s.tube_lights, 1);
  EXPECT_EQ(s.rectangle_lights, 1);
  EXPECT_TRUE(s.shadows);  // the glTF file's sun casts shadows
  EXPECT_TRUE(s.environment);
  EXPECT_EQ(s.irradiance_volumes, 1);
  EXPECT_EQ(s.reflection_probes, 1);
  EXPECT_TRUE(s.glossy_materials);
  EXPECT_NEAR(s.aperture, 0.01, 1e-7);
  EXPECT_FLOAT_EQ(v.environment.intensity, 0.5f);
  EXPECT_TRUE(v.environment.path.empty());
  EXPECT_FLOAT_EQ(v.exposure, -1.0f);
  EXPECT_NEAR(v.sphere_lights[0].center.z, 3.0f, 1e-6f);
  EXPECT_FLOAT_EQ(v.sphere_lights[0].radiance.x, 20.0f);
  EXPECT_TRUE(v.sphere_lights[0].casts_shadows);  // area lights cast shadows unless told not to
  EXPECT_FALSE(v.rect_lights.at(0).casts_shadows);
  EXPECT_NEAR(v.directional_lights.size(), 2u, 0);
  EXPECT_NEAR(v.camera.vertical_fov, glm::radians(45.0f), 1e-6f);
  // The override applies to every mesh of cube.obj, which hangs under "stage".
  int gold = -1;
  for (size_t i = 0; i < v.materials.size(); ++i)
    if (v.materials[i].name == "gold") gold = static_cast<int>(i);
  size_t gold_draws = 0, uncaptured = 0;
  for (const auto& d : v.draws) {
    uncaptured += d.captured_by_probes ? 0 : 1;
    if (d.material != gold) continue;
    ++gold_draws;
    EXPECT_NEAR(d.world[3].y, 1.0f, 1e-6f);  // moved with the stage
    EXPECT_FALSE(d.captured_by_probes);      // "captured_by_probes" applies to the model's meshes too
  }
  EXPECT_EQ(gold_draws, 2u);  // cube.obj has two materials, so two meshes
  EXPECT_EQ(uncaptured, 3u);  // and the ball; every other draw is captured
  // The camera is the one the file placed (the glTF file's camera has a higher index).
  EXPECT_NEAR(v.camera.position.z, 6.0f, 1e-5f);
  EXPECT_FLOAT_EQ(v.camera.aperture, 0.01f);
}

TEST(SceneFile, EveryErrorIsReportedWithItsPosition) {
  const char* text = R"({
  "format": "lumagraph-world/1",
  "materials": {
    "red": {"base_color": [0.8, 0.1], "roughnes": 0.5},
    "blue": {"metalness": 2}
  },
  "entities": [
    {"name": "a", "shape": {"type": "spere", "radius": 1}},
    {"name": "b", "parent": "c", "material": "rde", "shape": {"type": "box"}},
    {"name": "c", "point_light": {"intensity": "bright"}, "sphere_lite": {}},
    {"name": "d", "transform": {"position": [0, 0, 0], "look_at": [0, 0, 0]}},
    {"name": "e", "model": "/etc/passwd"},
    {"name": "f", "model": "../../../CMakeLists.txt"},
    {"name": "g", "model": "missing.obj"},
    {"name": "h", "camera": {"vertical_fov": 200}, "rect_light": {"two_sided": 1}}
  ]
})";
  std::vector<std::string> errors = errors_of(text);
  std::vector<std::string> expected = {
      "4:27: error: 'base_color' must be an array of 3 numbers from 0 to 1, found 2 items (/materials/red/base_color)",
      "4:51: error: unknown key 'roughnes' in material 'red'; did you mean 'roughness'? (/materials/red/roughnes)",
      "5:27: error: 'metalness' must be a number from 0 to 1, found 2 (/materials/blue/metalness)",
      "8:37: error: unknown shape 'spere'; did you mean 'sphere'? (/entities/0/shape/type)",
      "9:29: error: no entity named 'c' is listed before this one (/entities/1/parent)",
      "9:46: error: no material named 'rde' in 'materials'; did you mean 'red'? (/entities/1/material)",
      "9:62: error: a shape needs 'size' (/entities/1/shape)",
      "10:48: error: 'intensity' must be a number from 0 to 1e+09 (W/sr), found a string "
      "(/entities/2/point_light/intensity)",
      "10:74: error: unknown key 'sphere_lite' in an entity; did you mean 'sphere_light'? (/entities/2/sphere_lite)",
      "11:67: error: 'look_at' must differ from the position (/entities/3/transform/look_at)",
  };
  ASSERT_GE(errors.size(), expected.size() + 4) << testing::PrintToString(errors);
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(errors[i], expected[i]);
  // Paths: absolute and escaping ones are refused, missing files named; the checks of
  // graph/asset_paths.h word them.
  EXPECT_EQ(errors[10].rfind("12:28: error: '/etc/passwd' resolves to /etc/passwd, outside the allowed asset roots", 0),
            0u)
      << errors[10];
  EXPECT_EQ(errors[11].rfind("13:28: error: '../../../CMakeLists.txt' resolves to", 0), 0u) << errors[11];
  EXPECT_NE(errors[11].find("outside the allowed asset roots"), std::string::npos);
  EXPECT_EQ(errors[12].rfind("14:28: error: 'missing.obj' does not exist", 0), 0u) << errors[12];
  EXPECT_EQ(errors[13],
            "15:46: error: 'vertical_fov' must be a number from 1 to 179 (degrees), found 200 "
            "(/entities/7/camera/vertical_fov)");
  EXPECT_EQ(errors[14], "15:80: error: 'two_sided' must be true or false, found 1 (/entities/7/rect_light/two_sided)");
  EXPECT_EQ(errors.size(), 15u) << testing::PrintToString(errors);
}

TEST(SceneFile, SpotLightAnglesAreChecked) {
  std::vector<std::string> errors = errors_of(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "a", "spot_light": {"inner_angle": 40, "outer_angle": 30}},
    {"name": "b", "spot_light": {"inner_angle": 60}},
    {"name": "c", "spot_light": {"outer_angle": 95, "inner_angle": 50}},
    {"name": "d", "spot_light": {"inner_angle": -1, "intensity": -5, "shadows": "on"}}
  ]})");
  EXPECT_EQ(errors, (std::vector<std::string>{
                        "2:49: error: 'inner_angle' (40 degrees) must not exceed 'outer_angle' (30 degrees) "
                        "(/entities/0/spot_light/inner_angle)",
                        // The default outer angle is 45 degrees, as glTF's.
                        "3:49: error: 'inner_angle' (60 degrees) must not exceed 'outer_angle' (45 degrees) "
                        "(/entities/1/spot_light/inner_angle)",
                        // Out of range alone: the comparison would test inner against a default.
                        "4:49: error: 'outer_angle' must be a number from 0 to 90 (degrees), found 95 "
                        "(/entities/2/spot_light/outer_angle)",
                        "5:49: error: 'inner_angle' must be a number from 0 to 90 (degrees), found -1 "
                        "(/entities/3/spot_light/inner_angle)",
                        "5:66: error: 'intensity' must be a number from 0 to 1e+09 (W/sr), found -5 "
                        "(/entities/3/spot_light/intensity)",
                        "5:81: error: 'shadows' must be true or false, found a string "
                        "(/entities/3/spot_light/shadows)"}))
      << testing::PrintToString(errors);
}

// A non-finite probe size is refused at load with its line and column (by the JSON reader: no
// number in a scene file can be infinite), as is a "captured_by_probes" that is not a boolean.
TEST(SceneFile, NonFiniteProbeSizeAndBadCaptureFlagAreRefused) {
  EXPECT_EQ(errors_of(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "a", "reflection_probe": {"extent": [1, 1e999, 1]}}
  ]})"),
            (std::vector<std::string>{"2:54: error: number 1e999 is out of range (the largest is about 1.8e308)"}));
  EXPECT_EQ(
      errors_of(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "a", "shape": {"type": "bunny"}, "captured_by_probes": "no"}
  ]})"),
      (std::vector<std::string>{
          "2:69: error: 'captured_by_probes' must be true or false, found a string (/entities/0/captured_by_probes)"}));
}

// A probe's influence and proxy reach SceneView as written; the proxy defaults to the influence.
TEST(SceneFile, ReflectionProbesLoad) {
  World w = parse_scene_file(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "room", "transform": {"position": [1, 2, 3]},
     "reflection_probe": {"extent": [4, 1.5, 3], "blend": 0.5, "proxy": {"extent": [5, 2, 3.5], "offset": [0, 0.5, 0]}}},
    {"name": "ball", "reflection_probe": {"radius": 2, "blend": 0.25}}
  ]})",
                             fake_path());
  SceneView v = make_scene_view(w, 1.0f);
  ASSERT_EQ(v.reflection_probes.size(), 2u);
  const ReflectionProbe& room = v.reflection_probes[0].probe;
  EXPECT_EQ(room.influence, ProbeShape::box);
  EXPECT_EQ(room.extent, glm::vec3(4.0f, 1.5f, 3.0f));
  EXPECT_FLOAT_EQ(room.blend, 0.5f);
  EXPECT_EQ(room.proxy, ProbeShape::box);
  EXPECT_EQ(room.proxy_extent, glm::vec3(5.0f, 2.0f, 3.5f));
  EXPECT_EQ(room.proxy_offset, glm::vec3(0.0f, 0.5f, 0.0f));
  EXPECT_EQ(v.reflection_probes[0].world[3], glm::vec4(1, 2, 3, 1));
  const ReflectionProbe& ball = v.reflection_probes[1].probe;
  EXPECT_EQ(ball.influence, ProbeShape::sphere);
  EXPECT_EQ(ball.proxy, ProbeShape::sphere);
  EXPECT_FLOAT_EQ(ball.proxy_radius, 2.0f);
  EXPECT_EQ(v.summary().reflection_probes, 2);
}

// Zero and out-of-range sizes (a non-finite number cannot pass the JSON reader, which refuses
// 1e999 itself), both shapes at once, a blend deeper than the volume, and proxies that do not
// contain the probe, each at its value's line and column.
TEST(SceneFile, ReflectionProbesAreChecked) {
  std::vector<std::string> errors = errors_of(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "a", "reflection_probe": {"extent": [1, 0, 1]}},
    {"name": "b", "reflection_probe": {"radius": 2e6, "blend": -1}},
    {"name": "c", "reflection_probe": {"extent": [2, 1, 2], "radius": 1}},
    {"name": "d", "reflection_probe": {"extent": [2, 1, 2], "blend": 1.5}},
    {"name": "e", "reflection_probe": {"radius": 1, "proxy": {"extent": [1, 1, 1], "offset": [0, 2, 0]}}},
    {"name": "f", "reflection_probe": {"radius": 1, "proxy": {"radius": 0.5, "offset": [0.3, 0.4, 0]}}},
    {"name": "g", "reflection_probe": {"radius": 1, "proxy": {"radius": 2, "shape": "box"}}}
  ]})");
  EXPECT_EQ(
      errors,
      (std::vector<std::string>{
          "2:54: error: 'extent' must be an array of 3 numbers from 0.001 to 1e+06, found 0 "
          "(/entities/0/reflection_probe/extent/1)",
          "3:50: error: 'radius' must be a number from 0.001 to 1e+06 (metres), found 2e+06 "
          "(/entities/1/reflection_probe/radius)",
          "3:64: error: 'blend' must be a number from 0 to 1e+06 (metres), found -1 "
          "(/entities/1/reflection_probe/blend)",
          "4:71: error: give either 'extent' (a box) or 'radius' (a sphere) (/entities/2/reflection_probe/radius)",
          "5:70: error: 'blend' (1.5 m) must not exceed the influence volume's smallest extent (1 m) "
          "(/entities/3/reflection_probe/blend)",
          "6:62: error: the proxy must contain the probe (the entity's origin) (/entities/4/reflection_probe/proxy)",
          "7:62: error: the proxy must contain the probe (the entity's origin) (/entities/5/reflection_probe/proxy)",
          "8:85: error: unknown key 'shape' in the reflection probe's proxy; expected extent, radius, offset "
          "(/entities/6/reflection_probe/proxy/shape)"}))
      << testing::PrintToString(errors);
}

// Euler angles are yaw (Y), pitch (X), roll (Z) applied as R = Ry Rx Rz; quaternions are
// normalised. Tolerance 1e-5.
TEST(SceneFile, RotationConventions) {
  World w = parse_scene_file(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "yaw", "transform": {"rotation": [0, 90, 0]}},
    {"name": "pitch yaw", "transform": {"rotation": [90, 90, 0]}},
    {"name": "quat", "transform": {"rotation": [0, 0, 2, 2], "scale": [1, 2, 3]}}
  ]})",
                             fake_path());
  auto forward = [&](uint32_t index) {
    Entity e{index, 0};
    return glm::vec3(w.world_matrix(e) * glm::vec4(0, 0, -1, 0));
  };
  glm::vec3 yaw = forward(0), pitch_yaw = forward(1), quat = forward(2);
  EXPECT_NEAR(yaw.x, -1.0f, 1e-5f);             // -Z turned 90 degrees left about Y
  EXPECT_NEAR(pitch_yaw.y, 1.0f, 1e-5f);        // pitched up first, so the yaw leaves it up
  EXPECT_NEAR(glm::length(quat), 3.0f, 1e-5f);  // 90 degrees about Z leaves -Z, scaled by 3
  EXPECT_NEAR(quat.z, -3.0f, 1e-5f);
}

TEST(SceneFile, ConflictsAndDuplicates) {
  std::vector<std::string> errors = errors_of(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "a", "model": "cube.obj", "shape": {"type": "bunny"}},
    {"name": "a", "transform": {"rotation": [0, 0, 0], "look_at": [1, 0, 0]}},
    {"shape": {"radius": 1}, "material": 5},
    {"material": "x"}
  ]})");
  std::vector<std::string> expected = {
      "2:49: error: an entity has a 'model' or a 'shape', not both (/entities/0/shape)",
      "3:14: error: another entity is already named 'a' (/entities/1/name)",
      "3:67: error: a transform has a 'rotation' or a 'look_at', not both (/entities/1/transform/look_at)",
      "4:15: error: a shape needs 'type' (/entities/2/shape)",
      "4:42: error: 'material' must be the name of a material in 'materials' (/entities/2/material)",
      "5:18: error: no material named 'x' in 'materials' (/entities/3/material)",
      "5:18: error: a material needs a 'model' or a 'shape' to apply to (/entities/3/material)",
  };
  EXPECT_EQ(errors, expected);
}

TEST(SceneFile, EnvironmentPaths) {
  std::vector<std::string> errors = errors_of(R"({"format": "lumagraph-world/1", "entities": [],
    "environment": {"path": "cube.obj", "intensity": -1}})");
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0],
            "2:29: error: 'cube.obj' has the extension '.obj'; expected one of .hdr, .exr (/environment/path)");
  EXPECT_EQ(errors[1], "2:54: error: 'intensity' must be a number from 0 to 1e+09, found -1 (/environment/intensity)");
  fs::path shared = fs::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data" / "env";
  if (!fs::exists(shared / "grace.hdr")) GTEST_SKIP() << "no " << shared << " (../shared/data is absent)";
  std::string model = fs::relative(shared / "grace.hdr", data_dir()).string();
  World w = parse_scene_file(
      R"({"format": "lumagraph-world/1", "entities": [], "environment": {"path": ")" + model + R"("}})", fake_path(),
      AssetRoots{{shared.string()}});
  SceneView v = make_scene_view(w, 1.0f);
  EXPECT_EQ(v.environment.path, fs::canonical(shared / "grace.hdr").string());
}

TEST(SceneFile, MissingFile) {
  std::string path = data_dir() + "/nothing.json";
  try {
    load_world(path);
    FAIL() << "loaded a missing file";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": error: cannot open the file: No such file or directory");
  }
}

TEST(SceneFile, StructuralErrors) {
  EXPECT_EQ(errors_of("[]"),
            std::vector<std::string>{"1:1: error: expected a scene file as an object, found an array"});
  EXPECT_EQ(errors_of(R"({"format": "lumagraph-world/2", "entities": []})"),
            std::vector<std::string>{"1:12: error: expected \"format\": \"lumagraph-world/1\" (/format)"});
  EXPECT_EQ(errors_of(R"({"format": "lumagraph-world/1"})"),
            std::vector<std::string>{"1:1: error: a scene file needs 'entities'"});
  EXPECT_EQ(errors_of(R"({"format": "lumagraph-world/1", "entities": [3]})"),
            std::vector<std::string>{"1:46: error: expected an entity as an object, found 3 (/entities/0)"});
  // A syntax error comes from the JSON reader with its position.
  std::vector<std::string> syntax = errors_of("{\"format\": \"lumagraph-world/1\",\n \"entities\": [,]}");
  ASSERT_EQ(syntax.size(), 1u);
  EXPECT_EQ(syntax[0].rfind("2:15: error:", 0), 0u) << syntax[0];
}

TEST(SceneFile, ModelErrorsNameTheModelAndWhatIsWrong) {
  fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "scene-test-files";
  fs::create_directories(dir);
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  std::string scene = (dir / "scene.json").string();
  std::ofstream(scene) << R"({"format": "lumagraph-world/1", "entities": [{"model": "broken.obj"}]})";
  try {
    load_world(scene);
    FAIL() << "loaded a broken model";
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().items().size(), 1u);
    EXPECT_EQ(
        e.diagnostics().items()[0].to_string(),
        scene + ":1:56: error: 'broken.obj':4:7: vertex index 9 is beyond the file's 3 vertices (/entities/0/model)");
  }
}

TEST(SceneFile, AssetRootsAllowPathsOutsideTheScenesFolder) {
  fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "scene-test-files" / "nested";
  fs::create_directories(dir);
  std::string scene = (dir / "scene.json").string();
  std::string model = fs::relative(fs::path(data_dir()) / "cube.obj", dir).string();
  std::ofstream(scene) << R"({"format": "lumagraph-world/1", "entities": [{"model": ")" << model << R"("}]})";
  EXPECT_THROW(load_world(scene), SceneError);
  World w = load_world(scene, {AssetRoots{{dir.string(), data_dir()}}, {}});
  EXPECT_EQ(w.count<MeshRenderer>(), 2u);
}

// The example worlds load; the Stanford bunny one reaches ../shared/data through an asset root.
TEST(SceneFile, ExampleWorldsLoad) {
  fs::path examples = fs::path(LUMAGRAPH_SOURCE_DIR) / "examples" / "worlds";
  fs::path shared = fs::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data";
  size_t loaded = 0;
  for (const auto& entry : fs::directory_iterator(examples)) {
    if (entry.path().extension() != ".json") continue;
    if (entry.path().stem().string().ends_with("-baked")) {
      // Its "occlusion" bakes need the nodes' reader: tests/occlusion/baked_test.cpp loads it.
      std::cout << "skipping " << entry.path() << ": it carries occlusion bakes\n";
      continue;
    }
    bool needs_shared = entry.path().stem() == "stanford-bunny";
    if (needs_shared && !fs::exists(shared / "mesh" / "bunny.obj")) {
      std::cout << "skipping " << entry.path() << ": no " << shared << "\n";
      continue;
    }
    WorldLoadOptions options;
    if (needs_shared) options.asset_roots.roots = {examples.string(), shared.string()};
    World w = load_world(entry.path().string(), options);
    SceneView v = make_scene_view(w, 16.0f / 9.0f);
    EXPECT_FALSE(v.draws.empty()) << entry.path();
    const SceneSummary s = v.summary();
    const int lights =
        s.directional_lights + s.point_lights + s.spot_lights + s.sphere_lights + s.tube_lights + s.rectangle_lights;
    EXPECT_TRUE(lights > 0 || s.environment) << entry.path() << " is lit";  // two-spheres: the environment alone
    ++loaded;
  }
  EXPECT_GE(loaded, 1u);
}

// A planar reflector's mesh must be flat and have a side to reflect from (how flat: MeshPlane's
// tests); its plane reaches the scene view in world space, once for every piece of one floor.
TEST(SceneFile, PlanarReflectorsMustBeFlat) {
  std::vector<std::string> errors = errors_of(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "planar_reflector": true},
    {"name": "bare", "planar_reflector": true},
    {"name": "quad", "shape": {"type": "quad", "size": [1, 1]}, "planar_reflector": "yes"}
  ]})");
  EXPECT_EQ(errors, (std::vector<std::string>{
                        // A closed mesh faces every way: its triangles' normals cancel.
                        "2:86: error: a planar reflector's mesh must be flat and face one way; 'sphere' has no "
                        "side to reflect from (/entities/0/planar_reflector)",
                        "3:42: error: 'planar_reflector' needs a 'model' or a 'shape' to reflect with "
                        "(/entities/1/planar_reflector)",
                        "4:85: error: 'planar_reflector' must be true or false, found a string "
                        "(/entities/2/planar_reflector)"}));
}

TEST(SceneFile, PlanarReflectorPlanesAreInWorldSpaceAndShared) {
  World w = parse_scene_file(R"({"format": "lumagraph-world/1", "entities": [
    {"name": "left", "shape": {"type": "quad", "size": [1, 1]}, "transform": {"position": [-1, 0.25, 0]},
     "planar_reflector": true},
    {"name": "right", "shape": {"type": "quad", "size": [1, 1]}, "transform": {"position": [1, 0.25, 0]},
     "planar_reflector": true},
    {"name": "wall", "shape": {"type": "quad", "size": [2, 2]},
     "transform": {"position": [0, 1, -3], "rotation": [90, 0, 0]}, "planar_reflector": true},
    {"name": "plain", "shape": {"type": "quad", "size": [1, 1]}, "transform": {"position": [0, 2, 0]}}
  ]})",
                             fake_path());
  const SceneView v = make_scene_view(w, 1.0f);
  ASSERT_EQ(v.planar_reflectors.size(), 2u);  // the two floor quads are one plane
  EXPECT_EQ(v.summary().planar_reflectors, 2);
  EXPECT_TRUE(v.summary().has(SceneFeature::planar_reflectors));
  // The floor faces +Y at y = 0.25: n . p + w = 0 with w = -0.25.
  EXPECT_NEAR(glm::distance(glm::vec3(v.planar_reflectors[0]), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(v.planar_reflectors[0].w, -0.25f, 1e-6f);
  // The wall, +Y turned 90 degrees about X, faces +Z at z = -3.
  EXPECT_NEAR(glm::distance(glm::vec3(v.planar_reflectors[1]), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_NEAR(v.planar_reflectors[1].w, 3.0f, 1e-5f);
}

TEST(SceneFile, GalleryHasEveryLightKind) {
  World w = load_world(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/worlds/gallery.json");
  SceneSummary s = make_scene_view(w, 16.0f / 9.0f).summary();
  EXPECT_EQ(s.directional_lights, 1);
  EXPECT_EQ(s.point_lights, 1);
  EXPECT_EQ(s.spot_lights, 1);
  EXPECT_EQ(s.sphere_lights, 1);
  EXPECT_EQ(s.tube_lights, 1);
  EXPECT_EQ(s.rectangle_lights, 1);
  EXPECT_EQ(s.irradiance_volumes, 1);
  EXPECT_EQ(s.reflection_probes, 1);
  EXPECT_TRUE(s.has(SceneFeature::thin_lens_camera));
}

}  // namespace
}  // namespace lg
