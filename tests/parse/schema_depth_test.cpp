// A 3D texture's depth in a schema ("depth": a count or "param:NAME"): read into the size rule,
// required of every texture3d output and resource, refused on other kinds and for values that
// are not a count or a number param, each error at the key's line and column.
#include <gtest/gtest.h>

#include <string>

#include "graph/schema_reader.h"

namespace lg {
namespace {

// Line 4 holds the resource.
std::string schema_with_resource(const std::string& resource) {
  return R"({ "type": "test.volume", "doc": "A node with a volume.",
  "params": [ { "name": "grid", "type": "int", "default": 16, "min": 4, "max": 64, "doc": "Cells." },
              { "name": "mode", "type": "enum", "default": "a", "values": ["a", "b"], "doc": "How." } ],
  "resources": [ )" +
         resource + R"( ],
  "passes": [ { "name": "run", "queue": "compute", "uses": {} } ] })";
}

std::string errors_of(const std::string& resource) {
  Diagnostics d("volume.json");
  EXPECT_FALSE(read_node_schema(schema_with_resource(resource), d));
  return d.to_string();
}

TEST(SchemaDepth, ReadsAParamOrACount) {
  Diagnostics d("volume.json");
  auto schema = read_node_schema(
      schema_with_resource(
          R"({ "name": "grid", "type": "texture3d:hdr", "extent": "param:grid", "depth": "param:grid", "doc": "." },
                { "name": "fixed", "type": "texture3d:mask", "extent": [8, 4], "depth": 2, "doc": "." })"),
      d);
  ASSERT_TRUE(schema) << d.to_string();
  ASSERT_EQ(schema->resources.size(), 2u);
  EXPECT_EQ(schema->resources[0].size.depth_param, schema->find_param("grid"));
  EXPECT_EQ(schema->resources[1].size.depth_param, -1);
  EXPECT_EQ(schema->resources[1].size.depth_fixed, 2u);
}

TEST(SchemaDepth, AThreeDTextureWithoutOneIsRefused) {
  const std::string text = errors_of(R"({ "name": "grid", "type": "texture3d:hdr", "extent": "param:grid", "doc": "." })");
  EXPECT_NE(text.find("volume.json:4:"), std::string::npos) << text;
  EXPECT_NE(text.find("/resources/0"), std::string::npos) << text;
  EXPECT_NE(text.find("a 3D texture needs \"depth\": a count or \"param:NAME\""), std::string::npos) << text;
}

TEST(SchemaDepth, AnotherKindWithOneIsRefused) {
  const std::string text = errors_of(R"({ "name": "flat", "type": "texture2d:hdr", "depth": 4, "doc": "." })");
  EXPECT_NE(text.find("volume.json:4:"), std::string::npos) << text;
  EXPECT_NE(text.find("/resources/0/depth"), std::string::npos) << text;
  EXPECT_NE(text.find("only a 3D texture (texture3d) has a depth, not texture2d"), std::string::npos) << text;
}

TEST(SchemaDepth, ValuesThatAreNotACountOrANumberParamAreRefused) {
  for (const char* depth : {"0", "2.5", "\"grid\"", "[4, 4]"}) {
    SCOPED_TRACE(depth);
    const std::string text = errors_of(R"({ "name": "v", "type": "texture3d:hdr", "depth": )" + std::string(depth) +
                                       R"(, "doc": "." })");
    EXPECT_NE(text.find("volume.json:4:"), std::string::npos) << text;
    EXPECT_NE(text.find("expected a count from 1 to 65536 or \"param:NAME\""), std::string::npos) << text;
  }
  std::string text = errors_of(R"({ "name": "v", "type": "texture3d:hdr", "depth": "param:mode", "doc": "." })");
  EXPECT_NE(text.find("volume.json:4:"), std::string::npos) << text;
  EXPECT_NE(text.find("'mode' is not a number param"), std::string::npos) << text;
  text = errors_of(R"({ "name": "v", "type": "texture3d:hdr", "depth": "param:cells", "doc": "." })");
  EXPECT_NE(text.find("no param named 'cells'"), std::string::npos) << text;
}

}  // namespace
}  // namespace lg
