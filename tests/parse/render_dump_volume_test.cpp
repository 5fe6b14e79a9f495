// `lumagraph render --dump` writes gi.lpv's and gi.voxel's optional volume outputs, which the
// graph leaves unlinked, as VTK image data (one .vti a mip) of the plan's 3D extent, with values
// checked on a tiny world: a 2 x 2 m grey floor (a quad facing up) under a sun straight down.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/parse/cli_runner.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using parse_test::lumagraph;
using parse_test::Outcome;
using parse_test::read_text;
using parse_test::TempDir;
using parse_test::write_text;

// Albedo 0.5 under 2 W/m^2: the floor (4 m^2) reflects 0.5 x 2 x 4 = 4 W a channel.
constexpr const char* kWorld = R"({ "format": "lumagraph-world/1", "name": "floor",
  "materials": { "grey": { "base_color": [0.5, 0.5, 0.5], "roughness": 0.9 } },
  "entities": [
    { "name": "floor", "shape": { "type": "quad", "size": [2, 2] }, "material": "grey" },
    { "name": "sun", "transform": { "rotation": [-90, 0, 0] }, "directional_light": { "irradiance": 2 } },
    { "name": "camera", "transform": { "position": [0, 2, 3], "look_at": [0, 0, 0] }, "camera": {} } ] })";
constexpr double kReflectedFlux = 4.0;  // W a channel

std::string graph_of(const std::string& node) {
  return R"({ "format": "lumagraph/1", "nodes": [ { "id": "gbuf", "type": "scene.gbuffer" }, )" + node +
         R"(, { "id": "out", "type": "output.display" } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "gi.gbuffer" }, { "from": "gi.irradiance", "to": "out.color" } ] })";
}

struct Volume {
  int dims[3] = {0, 0, 0};
  std::vector<float> rgba;
  const float* at(int i, int j, int k) const { return &rgba[4 * (size_t(i) + size_t(dims[0]) * (j + size_t(dims[1]) * k))]; }
};

// The dump's .vti as encode_vti writes it: the whole extent in the header, then one raw
// appended block (a UInt64 byte count, then little-endian Float32 values).
Volume read_vti(const std::string& path) {
  const std::string text = read_text(path);
  Volume v;
  const size_t extent = text.find("WholeExtent=\"");
  EXPECT_NE(extent, std::string::npos) << path;
  int e[6] = {};
  std::sscanf(text.c_str() + extent, "WholeExtent=\"%d %d %d %d %d %d\"", &e[0], &e[1], &e[2], &e[3], &e[4], &e[5]);
  for (int a = 0; a < 3; ++a) v.dims[a] = e[2 * a + 1] - e[2 * a] + 1;
  EXPECT_NE(text.find("Name=\"rgba\" NumberOfComponents=\"4\""), std::string::npos) << path;
  // XML allows no "--" inside a comment: VTK's reader refused the first dumps, whose comment
  // quoted the option.
  const size_t comment = text.find("<!--");
  if (comment != std::string::npos) {
    EXPECT_EQ(text.find("--", comment + 4), text.find("-->", comment + 4)) << path;
  }
  const size_t data = text.find('_', text.find("<AppendedData"));
  uint64_t bytes = 0;
  std::memcpy(&bytes, text.data() + data + 1, sizeof bytes);
  EXPECT_EQ(bytes, uint64_t(v.dims[0]) * v.dims[1] * v.dims[2] * 4 * sizeof(float)) << path;
  v.rgba.resize(bytes / sizeof(float));
  std::memcpy(v.rgba.data(), text.data() + data + 1 + sizeof bytes, bytes);
  return v;
}

Outcome render_with_dump(const TempDir& dir, const std::string& node) {
  write_text(dir.file("world.json"), kWorld);
  write_text(dir.file("graph.json"), graph_of(node));
  return lumagraph({"render", dir.file("graph.json"), "--scene", dir.file("world.json"), "--size", "32x18", "--out",
                    dir.file("frame.png"), "--dump", dir.file("dump"), "--validate"});
}

// gi.lpv over an explicit box 4 x 2 x 4 m, grid 8: cells of 0.5 m, 8 x 4 x 8 of them in the
// 8^3 output, so alpha is 1 in the rows y < 4 and 0 above. With no propagation the sum is what
// was injected: every virtual point light, of flux F, a cosine lobe whose L0 coefficient is
// F / pi x sqrt(pi) / 2 in W/sr, stored as radiance (over cell^2), and the output's rgb is that
// times sqrt(pi) / 2 (mean irradiance), so the output times cell^2 sums to F / 4 over the grid.
// Tolerance 3%: the RSM (128 texels over the floor's bounding sphere, 2.83 m) covers the 2 m
// floor with 90 or 91 texels a side where it has 90.4 (at most 1.1% a side), plus half floats.
TEST(RenderDumpVolume, WritesTheLpvGridWithTheInjectedLight) {
  TempDir dir;
  const Outcome r = render_with_dump(dir, R"({ "id": "gi", "type": "gi.lpv", "params": { "grid": 8, "iterations": 0,
      "rsm_size": 128, "box_min": [-2, -1, -2], "box_max": [2, 1, 2], "resolution_scale": 1 } })");
  ASSERT_EQ(r.status, 0) << r.err;
  const Volume v = read_vti(dir.file("dump/gi.volume.vti"));
  ASSERT_EQ(v.dims[0], 8);
  ASSERT_EQ(v.dims[1], 8);
  ASSERT_EQ(v.dims[2], 8);
  EXPECT_FALSE(fs::exists(dir.file("dump/gi.volume.mip1.vti")));
  double sum[3] = {0, 0, 0};
  int wrong_alpha = 0, light_outside = 0;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const float* t = v.at(i, j, k);
        wrong_alpha += t[3] != (j < 4 ? 1.0f : 0.0f);
        for (int c = 0; c < 3; ++c) {
          sum[c] += t[c] * 0.25;  // x cell^2
          light_outside += j >= 4 && t[c] != 0.0f;
        }
      }
  EXPECT_EQ(wrong_alpha, 0);
  EXPECT_EQ(light_outside, 0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], kReflectedFlux / 4.0, 0.03 * kReflectedFlux / 4.0) << "channel " << c;
}

// gi.voxel at resolution 8 over the floor's bounds (2 m): voxels of 0.25 m, 8 x 1 x 8 of them
// (a flat side gets one), so level 0 is opaque and lit in row y = 0 (the floor crosses every
// voxel of it) and empty above; the full chain of 8^3 comes as four files, each mip half the
// last, and mip 3's one texel still holds the floor (opacity above 0).
TEST(RenderDumpVolume, WritesEveryMipOfTheVoxels) {
  TempDir dir;
  const Outcome r = render_with_dump(dir, R"({ "id": "gi", "type": "gi.voxel", "params": { "resolution": 8,
      "resolution_scale": 1 } })");
  ASSERT_EQ(r.status, 0) << r.err;
  const Volume level0 = read_vti(dir.file("dump/gi.volume.vti"));
  ASSERT_EQ(level0.dims[0], 8);
  ASSERT_EQ(level0.dims[1], 8);
  ASSERT_EQ(level0.dims[2], 8);
  int floor_not_opaque = 0, air_not_clear = 0, unlit_top = 0;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const float* t = level0.at(i, j, k);
        if (j == 0) {
          floor_not_opaque += !(t[3] > 0.5f);
          unlit_top += !(t[1] > 0.0f);  // the sun lights the floor's top
        } else {
          air_not_clear += t[3] != 0.0f || t[0] != 0.0f;
        }
      }
  EXPECT_EQ(floor_not_opaque, 0);
  EXPECT_EQ(air_not_clear, 0);
  EXPECT_EQ(unlit_top, 0);
  for (int mip = 1; mip < 4; ++mip) {
    const Volume m = read_vti(dir.file("dump/gi.volume.mip" + std::to_string(mip) + ".vti"));
    EXPECT_EQ(m.dims[0], 8 >> mip);
    EXPECT_EQ(m.dims[2], 8 >> mip);
    if (mip == 3) {
      EXPECT_GT(m.at(0, 0, 0)[3], 0.0f);
    }
  }
  EXPECT_FALSE(fs::exists(dir.file("dump/gi.volume.mip4.vti")));
}

}  // namespace
}  // namespace lg
