// What the preview offers and shows, without a window: the ports of a graph (G-buffer
// components each), how values become display pixels per encoding, exposure and channel, and
// the read-out text.
#include "editor/preview_display.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "editor/preview_ports.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace lg::editor {
namespace {

TEST(PreviewPorts, MainOutputThenEveryOutputPortAndEachGBufferComponent) {
  Diagnostics d;
  std::optional<Graph> g = load_graph_file(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/default.json", d);
  ASSERT_TRUE(g) << d.to_string();
  const std::vector<PreviewPort> ports = preview_ports(*g, builtin_registry());
  ASSERT_FALSE(ports.empty());
  EXPECT_TRUE(ports.front().name.empty());
  auto find = [&](const std::string& name) {
    return std::find_if(ports.begin(), ports.end(), [&](const PreviewPort& p) { return p.name == name; });
  };
  ASSERT_NE(find("gbuf.gbuffer.normal"), ports.end());
  EXPECT_EQ(find("gbuf.gbuffer.normal")->port.text(), "gbuf.gbuffer");
  EXPECT_EQ(find("gbuf.gbuffer.depth")->component, 0);
  EXPECT_EQ(find("gbuf.gbuffer.normal")->component, 1);
  EXPECT_EQ(find("gbuf.gbuffer"), ports.end()) << "a bundle is shown by component";
  for (const char* port : {"tonemap.color", "light.color", "sh.sh", "sky.cube", "gtao.ao", "gtao.bent_normals"})
    EXPECT_NE(find(port), ports.end()) << port;
}

PreviewImage one_pixel(float r, float g, float b, float a, PreviewEncoding encoding) {
  return PreviewImage{1, 1, {r, g, b, a}, encoding, 4, {}, {}, {}};
}

QRgb shown(const PreviewImage& image, double ev = 0, PreviewChannel channel = PreviewChannel::rgb) {
  return display_image(image, ev, channel).pixel(0, 0);
}

// Exact 8-bit values: sRGB(0.5) = 0.7354 -> 188, sRGB(0.125 * 4) the same.
TEST(PreviewDisplay, EachEncodingShowsItsValuesItsWay) {
  EXPECT_EQ(shown(one_pixel(0.5f, 0.5f, 0.5f, 1, PreviewEncoding::colour)), qRgb(188, 188, 188));
  EXPECT_EQ(shown(one_pixel(0.125f, 0, 2, 1, PreviewEncoding::colour), 2), qRgb(188, 0, 255));
  EXPECT_EQ(shown(one_pixel(0.5f, 0.25f, 1, 1, PreviewEncoding::display), 3), qRgb(128, 64, 255)) << "no exposure";
  EXPECT_EQ(shown(one_pixel(0.5f, 0.25f, 0, 1, PreviewEncoding::data)), qRgb(128, 64, 0)) << "no sRGB encode";
  EXPECT_EQ(shown(one_pixel(0.25f, 0.125f, 0, 1, PreviewEncoding::data), 1), qRgb(128, 64, 0));
}

TEST(PreviewDisplay, AChannelShowsAsGreyAndAOneChannelImageToo) {
  const PreviewImage image = one_pixel(0.5f, 0.25f, 1, 0.5f, PreviewEncoding::data);
  EXPECT_EQ(shown(image, 0, PreviewChannel::green), qRgb(64, 64, 64));
  EXPECT_EQ(shown(image, 2, PreviewChannel::alpha), qRgb(128, 128, 128)) << "alpha is not exposed";
  PreviewImage depth = one_pixel(0.25f, 0, 0, 1, PreviewEncoding::data);
  depth.channels = 1;
  EXPECT_EQ(shown(depth), qRgb(64, 64, 64));
}

TEST(PreviewDisplay, NonFinitePixelsShowMagenta) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(shown(one_pixel(nan, 0, 0, 1, PreviewEncoding::colour)), qRgb(255, 0, 255));
  EXPECT_EQ(shown(one_pixel(0, inf, 0, 1, PreviewEncoding::display)), qRgb(255, 0, 255));
}

TEST(PreviewDisplay, TheReadOutGivesThePixelsOwnValues) {
  PreviewImage image{2, 1, {0, 0, 0, 1, 0.123456789f, 2.5f, -1, 1}, PreviewEncoding::colour, 4, {}, {}, {}};
  EXPECT_EQ(pixel_readout(image, 1, 0), "x 1, y 0: 0.123457 2.5 -1 1");
  EXPECT_TRUE(pixel_readout(image, 2, 0).isEmpty());
  EXPECT_TRUE(pixel_readout(image, 0, -1).isEmpty());
}

}  // namespace
}  // namespace lg::editor
