// Scene summaries (`lumagraph compile --scene FILE`): the example scenes read, keys left out keep
// the default scene's values, and every wrong key or value is reported at its line and column
// with its JSON pointer, all of them at once.
#include "graph/scene_summary.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "graph/json_reader.h"
#include "parse_test_support.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

// Reads a summary from text; diagnostics are in `d`.
std::optional<SceneSummary> summary_from(std::string_view text, Diagnostics& d) {
  auto root = read_json(text, d);
  if (!root) return std::nullopt;
  return scene_summary_from_json(*root, d);
}

std::vector<std::string> lines(const Diagnostics& d) {
  std::vector<std::string> out;
  for (const auto& item : d.items()) out.push_back(item.to_string());
  return out;
}

TEST(ParseSceneSummary, EveryExampleSceneReads) {
  size_t count = 0;
  for (const auto& e : fs::directory_iterator(fs::path(LUMAGRAPH_SOURCE_DIR) / "examples" / "scenes")) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    Diagnostics d(e.path().string());
    EXPECT_TRUE(load_scene_summary(e.path().string(), d)) << d.to_string();
    EXPECT_TRUE(d.items().empty()) << d.to_string();
    ++count;
  }
  EXPECT_GE(count, 3u);
}

TEST(ParseSceneSummary, TheDefaultSceneFileMatchesTheEmbeddedDefault) {
  Diagnostics d;
  auto s = load_scene_summary(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/scenes/default.json", d);
  ASSERT_TRUE(s) << d.to_string();
  SceneSummary e = default_scene_summary();
  EXPECT_EQ(s->name, "default room");
  EXPECT_EQ(s->directional_lights, e.directional_lights);
  EXPECT_EQ(s->point_lights, e.point_lights);
  EXPECT_EQ(s->sphere_lights, e.sphere_lights);
  EXPECT_EQ(s->tube_lights, e.tube_lights);
  EXPECT_EQ(s->rectangle_lights, e.rectangle_lights);
  EXPECT_EQ(s->shadows, e.shadows);
  EXPECT_EQ(s->environment, e.environment);
  EXPECT_EQ(s->irradiance_volumes, e.irradiance_volumes);
  EXPECT_EQ(s->reflection_probes, e.reflection_probes);
  EXPECT_EQ(s->glossy_materials, e.glossy_materials);
  EXPECT_EQ(s->aperture, e.aperture);
  EXPECT_EQ(s->focus_distance, e.focus_distance);
}

TEST(ParseSceneSummary, EveryFieldIsRead) {
  // Each value differs from the default, so a field that is not read shows.
  Diagnostics d;
  auto s = summary_from(R"({
    "format": "lumagraph-scene-summary/1",
    "name": "all fields",
    "lights": { "directional": 0, "point": 3, "spot": 5, "sphere": 0, "tube": 0, "rectangle": 2, "shadows": false,
                "local_shadows": true },
    "environment": { "present": false },
    "probes": { "irradiance_volumes": 4, "reflection_probes": 1000000 },
    "materials": { "glossy": false, "blend": true, "emissive": true },
    "camera": { "aperture": 0.025, "focus_distance": 1.5 }
  })",
                        d);
  ASSERT_TRUE(s) << d.to_string();
  EXPECT_EQ(s->name, "all fields");
  EXPECT_EQ(s->directional_lights, 0);
  EXPECT_EQ(s->point_lights, 3);
  EXPECT_EQ(s->spot_lights, 5);
  EXPECT_EQ(s->sphere_lights, 0);
  EXPECT_EQ(s->tube_lights, 0);
  EXPECT_EQ(s->rectangle_lights, 2);
  EXPECT_FALSE(s->shadows);
  EXPECT_TRUE(s->local_shadows);
  EXPECT_FALSE(s->environment);
  EXPECT_EQ(s->irradiance_volumes, 4);
  EXPECT_EQ(s->reflection_probes, 1000000);
  EXPECT_FALSE(s->glossy_materials);
  EXPECT_TRUE(s->blend_materials);
  EXPECT_TRUE(s->emissive_materials);
  EXPECT_EQ(s->aperture, 0.025);
  EXPECT_EQ(s->focus_distance, 1.5);
  // And the features follow from them.
  EXPECT_TRUE(s->has(SceneFeature::area_lights));  // the rectangle lights
  EXPECT_TRUE(s->has(SceneFeature::spot_lights));
  EXPECT_TRUE(s->has(SceneFeature::local_shadow_casting_lights));
  EXPECT_FALSE(s->has(SceneFeature::shadow_casting_lights));
  EXPECT_TRUE(s->has(SceneFeature::thin_lens_camera));
  EXPECT_TRUE(s->has(SceneFeature::blend_materials));
  EXPECT_TRUE(s->has(SceneFeature::emissive_materials));
  EXPECT_FALSE(s->has(SceneFeature::environment_light));
}

TEST(ParseSceneSummary, KeysLeftOutKeepTheDefaultScene) {
  Diagnostics d;
  auto s = summary_from(R"({"format": "lumagraph-scene-summary/1", "camera": {"aperture": 0.05}})", d);
  ASSERT_TRUE(s) << d.to_string();
  SceneSummary e = default_scene_summary();
  EXPECT_EQ(s->aperture, 0.05);
  EXPECT_EQ(s->focus_distance, e.focus_distance);
  EXPECT_EQ(s->sphere_lights, e.sphere_lights);
  EXPECT_EQ(s->environment, e.environment);
  EXPECT_EQ(s->name, "");  // unnamed: the CLI names it after the file
}

TEST(ParseSceneSummary, EveryWrongKeyAndValueIsReportedWithItsPlace) {
  Diagnostics d("scene.json");
  auto s = summary_from(R"({
  "format": "lumagraph-scene-summary/1",
  "lights": { "directional": "1", "point": -1, "sphere": 1.5, "shadows": 1, "spots": 2 },
  "camera": { "aperture": -0.1, "focus_distance": "far" },
  "environment": true,
  "materials": { "glossy": "yes" },
  "probes": { "irradiance_volumes": 2000000 },
  "sky": {},
  "name": 5
})",
                        d);
  EXPECT_FALSE(s);
  d.sort_by_position();
  const std::string count = "expected a whole number from 0 to 1000000";
  const std::string length = "expected a length in metres from 0 to 1000000";
  EXPECT_EQ(lines(d),
            (std::vector<std::string>{
                "scene.json:3:30: error: " + count + " (/lights/directional)",
                "scene.json:3:44: error: " + count + " (/lights/point)",
                "scene.json:3:58: error: " + count + " (/lights/sphere)",
                "scene.json:3:74: error: expected true or false (/lights/shadows)",
                "scene.json:3:86: error: unknown key 'spots' in lights; expected directional, point, spot, sphere, "
                "tube, rectangle, shadows, local_shadows (/lights/spots)",
                "scene.json:4:27: error: " + length + " (/camera/aperture)",
                "scene.json:4:51: error: " + length + " (/camera/focus_distance)",
                "scene.json:5:18: error: expected an object, found a boolean (/environment)",
                "scene.json:6:28: error: expected true or false (/materials/glossy)",
                "scene.json:7:37: error: " + count + " (/probes/irradiance_volumes)",
                "scene.json:8:10: error: unknown key 'sky'; expected format, name, lights, environment, probes, "
                "materials, occlusion or camera (/sky)",
                "scene.json:9:11: error: expected a string (/name)",
            }));
}

struct SummaryCase {
  const char* name;
  std::string text;
  std::string error;  // the whole diagnostic, as printed
};

void PrintTo(const SummaryCase& c, std::ostream* os) {
  *os << c.name;
}

class ParseSceneSummaryError : public testing::TestWithParam<SummaryCase> {};

TEST_P(ParseSceneSummaryError, IsReportedWithItsPlace) {
  Diagnostics d("s.json");
  EXPECT_FALSE(summary_from(GetParam().text, d));
  EXPECT_EQ(lines(d), std::vector<std::string>{GetParam().error});
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ParseSceneSummaryError,
    testing::Values(
        SummaryCase{"MissingFormat", "{\n  \"name\": \"x\"\n}",
                    "s.json:1:1: error: missing \"format\": \"lumagraph-scene-summary/1\""},
        SummaryCase{"GraphFormat", "{\n  \"format\": \"lumagraph/1\"\n}",
                    "s.json:2:13: error: expected \"lumagraph-scene-summary/1\" (/format)"},
        SummaryCase{"FormatNotAString", "{\n  \"format\": 1\n}",
                    "s.json:2:13: error: expected \"lumagraph-scene-summary/1\" (/format)"},
        SummaryCase{"RootIsAnArray", "\n  []", "s.json:2:3: error: expected a scene summary object, found an array"},
        SummaryCase{"SectionIsANumber", "{\"format\": \"lumagraph-scene-summary/1\",\n \"lights\": 2}",
                    "s.json:2:12: error: expected an object, found a number (/lights)"},
        SummaryCase{"SyntaxError", "{\"format\": \"lumagraph-scene-summary/1\",\n \"lights\": {\"point\": 1,}}",
                    "s.json:2:24: error: trailing comma before '}'"}),
    [](const testing::TestParamInfo<SummaryCase>& info) { return std::string(info.param.name); });

TEST(ParseSceneSummary, LoadingAFileNamesItInErrors) {
  parse_test::TempDir dir;
  std::string path = dir.file("scene.json");
  parse_test::write_text(path,
                         "{\n  \"format\": \"lumagraph-scene-summary/1\",\n  \"lights\": { \"point\": true }\n}\n");
  Diagnostics d(path);
  EXPECT_FALSE(load_scene_summary(path, d));
  EXPECT_EQ(lines(d),
            std::vector<std::string>{path + ":3:24: error: expected a whole number from 0 to 1000000 (/lights/point)"});
}

}  // namespace
}  // namespace lg
