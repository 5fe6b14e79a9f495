// The inspector shows a 3D texture as `lumagraph render --dump` writes it (encode_vti, the dump's
// own writer, makes one here with known values): the log scale spans four decades below the
// brightest texel, texels with alpha 0 are masked on the slices, the sliders move them, the mip
// chooser finds NAME.mip1.vti, another channel is made without reading the file again, and files
// that are not such a dump are refused naming the file.
// (`lumagraph-inspect --dumped` itself was run by hand for docs/images/inspect-lpv-volume.png: a
// process test of it took 15 s under the shared machine's load, over the 3 s a test may take.)
#include "editor/dumped_volume_view.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <cmath>
#include <fstream>

#include "editor/inspector_widget.h"
#include "nodes/raytrace/vti_file.h"
#include "qt_app.h"

namespace lg {
namespace {

// A w x h x d volume: texel (i, j, k) has rgb 10^-i (a decade a column, 1 at i = 0) and alpha 1,
// except in the slice k = d - 1, whose alpha is 0 (cells past a grid's counts).
void write_volume(const std::string& path, int w, int h, int d) {
  std::vector<float> rgba;
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const float v = float(std::pow(10.0, -i));
        rgba.insert(rgba.end(), {v, v, v, k == d - 1 ? 0.0f : 1.0f});
      }
  VtiImage image;
  image.dims = {uint32_t(w), uint32_t(h), uint32_t(d)};
  image.arrays.push_back({"rgba", 4, rgba});
  image.scalars = "rgba";
  std::ofstream(path, std::ios::binary) << encode_vti(image);
}

struct Dump {
  QTemporaryDir dir;
  std::string mip0 = dir.filePath("gi.volume.vti").toStdString();
  std::string mip1 = dir.filePath("gi.volume.mip1.vti").toStdString();
  Dump() {
    write_volume(mip0, 6, 4, 4);
    write_volume(mip1, 3, 2, 2);
  }
};

TEST(DumpedVolumeView, ShowsSlicesOnALogScaleWithAlphaZeroMasked) {
  test::qt_app();
  const Dump dump;
  InspectorWidget inspector;
  inspector.resize(480, 320);  // small: llvmpipe draws the volume rendering on every change
  inspector.show();
  ASSERT_TRUE(inspector.open_dumped_volume(QString::fromStdString(dump.mip0), VolumeChannel::luminance))
      << inspector.summary().toStdString();
  test::settle();
  std::optional<DumpedVolumeState> s = inspector.dumped_volume_state();
  ASSERT_TRUE(s);
  EXPECT_EQ(s->dims, (std::array<int, 3>{6, 4, 4}));
  EXPECT_EQ(s->slice, (std::array<int, 3>{3, 2, 1}));  // the middle of the texels with alpha 1 (k 0 to 2)
  // Luminance of grey v is v (the weights sum to 1, within float rounding).
  EXPECT_NEAR(s->value_range[1], 1.0, 1e-6);
  EXPECT_NEAR(s->value_range[0], 1e-4, 1e-10);
  EXPECT_EQ(s->lit_points, 6 * 4 * 3);  // alpha 1 and above 0
  // Slices x = 3 (4 x 4), y = 2 (6 x 4), z = 1 (6 x 4); alpha 0 in the row k = 3 of the first two.
  EXPECT_EQ(s->slice_points, 16 + 24 + 24);
  EXPECT_EQ(s->masked_points, 4 + 6);
  EXPECT_TRUE(inspector.summary().contains("gi.volume.vti")) << inspector.summary().toStdString();

  inspector.set_volume_slice(2, 100);  // clamped to the last slice, alpha 0 throughout
  s = inspector.dumped_volume_state();
  EXPECT_EQ(s->slice[2], 3);
  EXPECT_EQ(s->masked_points, 4 + 6 + 24);

  // Alpha is shown as it is, linear, nothing masked; the slices stay where they were.
  inspector.set_dumped_volume_channel(VolumeChannel::alpha);
  s = inspector.dumped_volume_state();
  EXPECT_EQ(s->channel, VolumeChannel::alpha);
  EXPECT_EQ(s->masked_points, 0);
  EXPECT_EQ(s->value_range, (std::array<double, 2>{0.0, 1.0}));
  EXPECT_EQ(s->slice[2], 3);

  // The mip chooser opens NAME.mip1.vti, the slices at the same place of the coarser grid.
  inspector.set_dumped_volume_mip(1);
  s = inspector.dumped_volume_state();
  EXPECT_EQ(s->dims, (std::array<int, 3>{3, 2, 2}));
  EXPECT_EQ(s->slice, (std::array<int, 3>{2, 1, 1}));  // 3 x 3 / 6 rounds to 2, 2 x 2 / 4 to 1, 3 x 2 / 4 to 2 clamped to 1
  EXPECT_TRUE(inspector.summary().contains("gi.volume.mip1.vti")) << inspector.summary().toStdString();
  EXPECT_TRUE(inspector.summary().contains("mip 1 of 2")) << inspector.summary().toStdString();
}

// A channel is made from the volume in memory: with the file gone, alpha and then luminance
// again show as they did when it was there.
TEST(DumpedVolumeView, AnotherChannelComesFromMemoryNotTheFile) {
  test::qt_app();
  Dump dump;
  InspectorWidget inspector;
  inspector.resize(480, 320);
  inspector.show();
  ASSERT_TRUE(inspector.open_dumped_volume(QString::fromStdString(dump.mip0), VolumeChannel::luminance));
  const DumpedVolumeState first = *inspector.dumped_volume_state();
  ASSERT_TRUE(QFile::remove(QString::fromStdString(dump.mip0)));

  inspector.set_dumped_volume_channel(VolumeChannel::alpha);
  std::optional<DumpedVolumeState> s = inspector.dumped_volume_state();
  ASSERT_TRUE(s) << inspector.summary().toStdString();
  EXPECT_EQ(s->channel, VolumeChannel::alpha);
  EXPECT_EQ(s->dims, first.dims);
  EXPECT_EQ(s->slice, first.slice);
  EXPECT_EQ(s->lit_points, 6 * 4 * 3);  // alpha 1 on the slices k 0 to 2

  inspector.set_dumped_volume_channel(VolumeChannel::luminance);
  s = inspector.dumped_volume_state();
  ASSERT_TRUE(s) << inspector.summary().toStdString();
  EXPECT_EQ(s->value_range, first.value_range);
  EXPECT_EQ(s->slice, first.slice);
  EXPECT_EQ(s->masked_points, first.masked_points);
  EXPECT_EQ(s->lit_points, first.lit_points);
  EXPECT_TRUE(inspector.summary().contains("gi.volume.vti")) << inspector.summary().toStdString();
}

TEST(DumpedVolumeView, FilesThatAreNotADumpedVolumeNameTheFile) {
  test::qt_app();
  const Dump dump;
  const std::string no_rgba = dump.dir.filePath("other.vti").toStdString();
  VtiImage image;
  image.dims = {2, 2, 2};
  const std::vector<float> values(8, 1.0f);
  image.arrays.push_back({"visibility", 1, values});
  std::ofstream(no_rgba, std::ios::binary) << encode_vti(image);
  const std::pair<std::string, const char*> cases[] = {
      {dump.dir.filePath("absent.vti").toStdString(), "no such file"},
      {no_rgba, "expected a point array rgba of 4 float components"},
      {dump.dir.filePath("gi.volume.exr").toStdString(), "no such file"}};
  for (const auto& [path, why] : cases) {
    InspectorWidget inspector;
    EXPECT_FALSE(inspector.open_dumped_volume(QString::fromStdString(path), VolumeChannel::luminance));
    EXPECT_FALSE(inspector.dumped_volume_state());
    EXPECT_TRUE(inspector.summary().startsWith(QString::fromStdString(path))) << inspector.summary().toStdString();
    EXPECT_TRUE(inspector.summary().contains(why)) << inspector.summary().toStdString();
  }
}

}  // namespace
}  // namespace lg
