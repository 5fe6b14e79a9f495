// Paths in params are untrusted: they resolve relative to the graph file and may not leave
// the asset roots, whether by "..", an absolute path or a symbolic link.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace lg {
namespace {
namespace fs = std::filesystem;

class AssetPaths : public testing::Test {
 protected:
  fs::path root, assets, outside;

  void SetUp() override {
    root = fs::temp_directory_path() / ("lumagraph-assets-" + std::to_string(::getpid()));
    assets = root / "game";
    outside = root / "elsewhere";
    fs::create_directories(assets / "sky");
    fs::create_directories(outside);
    std::ofstream(assets / "sky" / "day.hdr") << "#?RADIANCE\n";
    std::ofstream(outside / "secret.hdr") << "#?RADIANCE\n";
    std::ofstream(assets / "notes.txt") << "text\n";
    fs::create_symlink(outside / "secret.hdr", assets / "link.hdr");
  }
  void TearDown() override { fs::remove_all(root); }

  // Writes a graph loading `path` with env.load and compiles it; returns the diagnostics.
  Diagnostics compile_with_path(const std::string& path, AssetRoots roots = {}) {
    std::string text = "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [\n"
                       "    { \"id\": \"env\", \"type\": \"env.load\", \"params\": { \"path\": \"" + path + "\" } }\n"
                       "  ],\n  \"outputs\": [\"env.cube\"]\n}\n";
    std::ofstream(assets / "graph.json") << text;
    Diagnostics diagnostics;
    auto graph = load_graph_file((assets / "graph.json").string(), diagnostics);
    EXPECT_TRUE(graph) << diagnostics.to_string();
    CompileOptions options;
    options.roots = std::move(roots);
    if (graph) last_plan = compile(*graph, builtin_registry(), options, diagnostics).plan;
    return diagnostics;
  }
  std::optional<Plan> last_plan;

  static void expect_error(const Diagnostics& d, const std::string& text) {
    ASSERT_EQ(d.items().size(), 1u) << d.to_string();
    EXPECT_NE(d.items()[0].message.find(text), std::string::npos) << d.to_string();
    EXPECT_EQ(d.items()[0].pointer, "/nodes/0/params/path");
    EXPECT_EQ(d.items()[0].pos.line, 4u);
    EXPECT_EQ(d.items()[0].pos.column, 60u);  // the path string
  }
};

TEST_F(AssetPaths, RelativePathInsideTheGraphFolderResolvesToAnAbsolutePath) {
  Diagnostics d = compile_with_path("sky/day.hdr");
  ASSERT_TRUE(last_plan) << d.to_string();
  EXPECT_EQ(last_plan->nodes[0].params.find("path")->as_string(), fs::canonical(assets / "sky" / "day.hdr").string());
}

TEST_F(AssetPaths, DotDotThatStaysInsideIsFine) {
  Diagnostics d = compile_with_path("sky/../sky/day.hdr");
  EXPECT_TRUE(last_plan) << d.to_string();
}

TEST_F(AssetPaths, DotDotOutOfTheRootIsRefused) {
  expect_error(compile_with_path("../elsewhere/secret.hdr"), "outside the allowed asset roots");
}

TEST_F(AssetPaths, DeepDotDotIsRefused) {
  expect_error(compile_with_path("../../../../../../etc/passwd.hdr"), "outside the allowed asset roots");
}

TEST_F(AssetPaths, AbsolutePathOutsideIsRefused) {
  expect_error(compile_with_path((outside / "secret.hdr").string()), "outside the allowed asset roots");
}

TEST_F(AssetPaths, SymbolicLinkOutOfTheRootIsRefused) {
  expect_error(compile_with_path("link.hdr"), "outside the allowed asset roots");
}

TEST_F(AssetPaths, AnExtraAssetRootAllowsItsFiles) {
  Diagnostics d = compile_with_path((outside / "secret.hdr").string(), AssetRoots{{assets.string(), outside.string()}});
  EXPECT_TRUE(last_plan) << d.to_string();
}

TEST_F(AssetPaths, WrongExtensionIsRefused) {
  expect_error(compile_with_path("notes.txt"), "has the extension '.txt'; expected one of .hdr, .exr");
}

TEST_F(AssetPaths, MissingFileIsReported) {
  expect_error(compile_with_path("sky/night.hdr"), "'sky/night.hdr' does not exist");
}

TEST_F(AssetPaths, EmptyPathIsReported) {
  expect_error(compile_with_path(""), "the path is empty");
}

}  // namespace
}  // namespace lg
