// A schema's "presets": named param values the editor applies as one edit. The reader checks
// each value against its param's spec and refuses unknown params, values out of range and
// repeated names with the schema file's line and column; the built-in nodes with a time/error
// knob carry presets that pass those checks.
#include <gtest/gtest.h>

#include <string>

#include "graph/schema_reader.h"
#include "nodes/builtin_schemas.h"

namespace lg {
namespace {

// Line 6 holds the first preset's params, line 7 the second's.
std::string schema_with_presets(const std::string& first, const std::string& second) {
  return R"({ "type": "test.presets", "doc": "A node with presets.",
  "params": [ { "name": "samples", "type": "int", "default": 32, "min": 4, "max": 256, "doc": "Taps." },
              { "name": "mode", "type": "enum", "default": "fast", "values": ["fast", "exact"], "doc": "How." } ],
  "passes": [ { "name": "run", "queue": "compute", "uses": {} } ],
  "presets": [
    { "name": "low", "doc": "Cheap.", "params": )" +
         first + R"( },
    { "name": "high", "doc": "Close to the reference.", "params": )" +
         second + R"( } ] })";
}

TEST(SchemaPresets, ParseWithTheirParamsAndValues) {
  Diagnostics d("presets.json");
  auto schema =
      read_node_schema(schema_with_presets(R"({ "samples": 8 })", R"({ "samples": 128, "mode": "exact" })"), d);
  ASSERT_TRUE(schema) << d.to_string();
  ASSERT_EQ(schema->presets.size(), 2u);
  EXPECT_EQ(schema->presets[0].name, "low");
  EXPECT_EQ(schema->presets[0].doc, "Cheap.");
  ASSERT_EQ(schema->presets[1].values.size(), 2u);
  EXPECT_EQ(schema->presets[1].values[0].first, schema->find_param("samples"));
  EXPECT_EQ(schema->presets[1].values[0].second, JsonValue(128.0));
  EXPECT_EQ(schema->presets[1].values[1].first, schema->find_param("mode"));
  EXPECT_EQ(schema->presets[1].values[1].second, JsonValue("exact"));
}

TEST(SchemaPresets, AnUnknownParamIsRefusedWhereItIs) {
  Diagnostics d("presets.json");
  EXPECT_FALSE(read_node_schema(schema_with_presets(R"({ "sample": 8 })", R"({ "samples": 64 })"), d));
  const std::string text = d.to_string();
  EXPECT_NE(text.find("presets.json:6:"), std::string::npos) << text;
  EXPECT_NE(text.find("no param named 'sample'"), std::string::npos) << text;
  EXPECT_NE(text.find("/presets/0/params/sample"), std::string::npos) << text;
}

TEST(SchemaPresets, AValueOutOfRangeOrOfTheWrongKindIsRefused) {
  Diagnostics d("presets.json");
  EXPECT_FALSE(read_node_schema(schema_with_presets(R"({ "samples": 2 })", R"({ "mode": "slow" })"), d));
  const std::string text = d.to_string();
  EXPECT_EQ(d.error_count(), 2u) << text;
  EXPECT_NE(text.find("presets.json:6:"), std::string::npos) << text;
  EXPECT_NE(text.find("expected an integer from 4 to 256 (/presets/0/params/samples)"), std::string::npos) << text;
  EXPECT_NE(text.find("presets.json:7:"), std::string::npos) << text;
  EXPECT_NE(text.find("/presets/1/params/mode"), std::string::npos) << text;
}

TEST(SchemaPresets, RepeatedNamesAndEmptyPresetsAreRefused) {
  Diagnostics d("presets.json");
  std::string text = schema_with_presets(R"({})", R"({ "samples": 64 })");
  text.replace(text.find("\"high\""), 6, "\"low\"");
  EXPECT_FALSE(read_node_schema(text, d));
  EXPECT_NE(d.to_string().find("a second preset named 'low'"), std::string::npos) << d.to_string();
  EXPECT_NE(d.to_string().find("expected an object of param values, at least one (/presets/0/params)"),
            std::string::npos)
      << d.to_string();
}

// The nodes whose quality knob trades time for error, with benchmark numbers behind their presets.
TEST(SchemaPresets, TheBuiltInNodesWithAQualityKnobHavePresets) {
  for (const char* type : {"post.dof", "post.bloom", "post.bilateral", "post.taa", "occlusion.gtao"}) {
    const NodeSchema* schema = builtin_registry().find(type);
    ASSERT_TRUE(schema) << type;
    EXPECT_GE(schema->presets.size(), 2u) << type;
    for (const ParamPreset& preset : schema->presets) EXPECT_FALSE(preset.doc.empty()) << type << " " << preset.name;
  }
}

// "only_when_scaled" reads the value of the resource's scale param, so a fixed scale or none is
// refused where the key is.
TEST(SchemaResources, OnlyWhenScaledNeedsAScaleParam) {
  Diagnostics d("scaled.json");
  EXPECT_FALSE(read_node_schema(R"({ "type": "test.scaled", "doc": "A node.",
  "params": [ { "name": "scale", "type": "float", "default": 1, "min": 0.25, "max": 1, "doc": "Scale." } ],
  "resources": [ { "name": "guide", "type": "texture2d:hdr", "scale": 0.5, "only_when_scaled": true, "doc": "." } ],
  "passes": [ { "name": "run", "queue": "compute", "uses": {} } ] })",
                                d));
  const std::string text = d.to_string();
  EXPECT_NE(text.find("scaled.json:3:"), std::string::npos) << text;
  EXPECT_NE(text.find("/resources/0/only_when_scaled"), std::string::npos) << text;
  EXPECT_NE(text.find("needs \"scale\": \"param:NAME\""), std::string::npos) << text;
}

// An output fed to other nodes must have its real size: "only_when_scaled" is a resource's key.
TEST(SchemaResources, OnlyWhenScaledIsRefusedOnAnOutput) {
  Diagnostics d("scaled.json");
  EXPECT_FALSE(read_node_schema(R"({ "type": "test.scaled", "doc": "A node.",
  "params": [ { "name": "scale", "type": "float", "default": 1, "min": 0.25, "max": 1, "doc": "Scale." } ],
  "outputs": [ { "name": "guide", "type": "texture2d:hdr", "scale": "param:scale", "only_when_scaled": true, "doc": "." } ],
  "passes": [ { "name": "run", "queue": "compute", "uses": {} } ] })",
                                d));
  const std::string text = d.to_string();
  EXPECT_NE(text.find("scaled.json:3:"), std::string::npos) << text;
  EXPECT_NE(text.find("/outputs/0/only_when_scaled"), std::string::npos) << text;
  EXPECT_NE(text.find("only a resource can be a placeholder at scale 1"), std::string::npos) << text;
}

}  // namespace
}  // namespace lg
