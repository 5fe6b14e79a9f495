// The inspector shows a volume bake made at test time (a box on a floor, through the bake
// library): the slices' colour range is the file's, exactly the points inside the box are
// masked, the sliders move the slices, and broken or wrong files say which file and why.
#include "editor/bake_view.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "editor/inspector_widget.h"
#include "nodes/occlusion/bake/bake_outputs.h"
#include "qt_app.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ray_test_scenes.h"

namespace lg {
namespace {

constexpr std::array<uint32_t, 3> dims{9, 7, 8};

struct BakedBox {
  QTemporaryDir dir;
  BakeFile file;
  std::string lgbake, vti;

  BakedBox() {
    const WorldMesh mesh = make_world_mesh(test::scene_of(
        {test::floor_quad(3.0f), {make_box(glm::vec3(1.0f)), glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f})}}));
    const BakeDomain domain = BakeDomain::volume(mesh, dims);
    const RayScene scene(mesh.positions, mesh.indices);
    // 32 rays: enough to tell inside from outside, and the bake takes milliseconds.
    file.header = make_bake_header(domain, mesh, "box", {.rays = 32}, 1, 0, 1);
    file.data = run_bake(scene, domain, {.rays = 32}, 1, file.header.range);
    lgbake = dir.filePath("box.lgbake").toStdString();
    vti = dir.filePath("box.vti").toStdString();
    write_bake_outputs(lgbake, file);
  }

  // Points of the file with valid 0 on the slices through `slice`, counted per slice as the view
  // counts them (a point where two slices cross counts twice).
  long long invalid_on_slices(std::array<int, 3> slice) const {
    long long count = 0;
    for (uint32_t k = 0; k < dims[2]; ++k)
      for (uint32_t j = 0; j < dims[1]; ++j)
        for (uint32_t i = 0; i < dims[0]; ++i)
          if (file.data.valid[i + dims[0] * (j + dims[1] * k)] == 0.0f)
            count += (int(i) == slice[0]) + (int(j) == slice[1]) + (int(k) == slice[2]);
    return count;
  }
};

void expect_shows(InspectorWidget& inspector, const BakedBox& box) {
  const std::optional<VolumeSliceState> state = inspector.volume_state();
  ASSERT_TRUE(state) << inspector.summary().toStdString();
  for (int a = 0; a < 3; ++a) EXPECT_EQ(state->dims[a], int(dims[a]));
  float low = 1, high = 0;
  size_t valid_on_z_slice = 0;
  for (size_t p = 0; p < box.file.data.size(); ++p)
    if (box.file.data.valid[p] > 0) {
      low = std::min(low, box.file.data.visibility[p]), high = std::max(high, box.file.data.visibility[p]);
      valid_on_z_slice += int(p / (dims[0] * dims[1])) == state->slice[2];
    }
  EXPECT_DOUBLE_EQ(state->colour_range[0], low);
  EXPECT_DOUBLE_EQ(state->colour_range[1], high);
  EXPECT_EQ(state->slice_points, dims[1] * dims[2] + dims[0] * dims[2] + dims[0] * dims[1]);
  EXPECT_EQ(state->masked_points, box.invalid_on_slices(state->slice));
  EXPECT_GT(state->masked_points, 0) << "the middle slices cross the box: some points must be masked";
  // Grids under 16 points wide get an arrow at every valid point of the z slice.
  EXPECT_EQ(state->arrows, (long long)valid_on_z_slice);
}

TEST(BakeView, ShowsAVolumeBakeAsSlicesWithTheInsideMasked) {
  test::qt_app();
  const BakedBox box;
  InspectorWidget inspector;
  inspector.resize(900, 700);
  inspector.show();
  ASSERT_TRUE(inspector.open_bake(QString::fromStdString(box.vti))) << inspector.summary().toStdString();
  test::settle();
  expect_shows(inspector, box);
  EXPECT_TRUE(inspector.summary().contains("box.vti")) << inspector.summary().toStdString();

  // The mask is drawn: the view holds many more pixels of the mask's grey (0.55 -> 140,
  // lighting off; +-2 for the texture lookup) with slices through the box than with slices at
  // the grid's corner, where no point is inside.
  const auto grey_pixels = [&] {
    test::settle();
    const QImage image = inspector.grab().toImage();
    int grey = 0;
    for (int y = 0; y < image.height(); y += 2)
      for (int x = 0; x < image.width(); x += 2) {
        const QColor c = image.pixelColor(x, y);
        grey += std::abs(c.red() - 140) <= 2 && std::abs(c.green() - 140) <= 2 && std::abs(c.blue() - 140) <= 2;
      }
    return grey;
  };
  const int grey_through_box = grey_pixels();
  for (int a = 0; a < 3; ++a) inspector.set_volume_slice(a, 0);
  ASSERT_EQ(inspector.volume_state()->masked_points, box.invalid_on_slices({0, 0, 0}));
  ASSERT_EQ(inspector.volume_state()->masked_points, 0);
  EXPECT_GT(grey_through_box, grey_pixels() + 100) << "the masked points are not drawn grey";

  // A slider moves a slice, clamped to the grid; the mask follows it.
  inspector.set_volume_slice(0, 100);
  EXPECT_EQ(inspector.volume_state()->slice[0], int(dims[0]) - 1);
  inspector.set_volume_slice(1, int(dims[1]) / 2);
  inspector.set_volume_slice(2, int(dims[2]) / 2);
  expect_shows(inspector, box);
}

TEST(BakeView, TheLgbakeShowsTheSameAsTheVti) {
  test::qt_app();
  const BakedBox box;
  InspectorWidget inspector;
  ASSERT_TRUE(inspector.open_bake(QString::fromStdString(box.lgbake))) << inspector.summary().toStdString();
  expect_shows(inspector, box);
}

// Opens `path`, expects it refused with a message naming it and containing `why`.
void expect_refused(const std::string& path, const char* why) {
  test::qt_app();
  InspectorWidget inspector;
  EXPECT_FALSE(inspector.open_bake(QString::fromStdString(path)));
  EXPECT_FALSE(inspector.volume_state());
  EXPECT_TRUE(inspector.summary().startsWith(QString::fromStdString(path))) << inspector.summary().toStdString();
  EXPECT_TRUE(inspector.summary().contains(why)) << inspector.summary().toStdString();
}

TEST(BakeView, BrokenOrWrongFilesNameTheFile) {
  const BakedBox box;
  expect_refused(box.dir.filePath("absent.vti").toStdString(), "no such file");

  QFile vti(QString::fromStdString(box.vti));
  ASSERT_TRUE(vti.open(QIODevice::ReadOnly));
  const QByteArray whole = vti.readAll();
  vti.close();
  const auto write = [&](const char* name, const QByteArray& bytes) {
    const QString path = box.dir.filePath(name);
    QFile out(path);
    EXPECT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    return path.toStdString();
  };
  expect_refused(write("truncated.vti", whole.left(whole.size() / 2)), "damaged");
  expect_refused(write("text.vti", "not xml at all\n"), "not a VTK XML image data file");
  // Image data of the right shape without a bake's arrays (the names changed, same length).
  QByteArray renamed = whole;
  renamed.replace("\"visibility\"", "\"brightness\"");
  expect_refused(write("other.vti", renamed), "not an occlusion bake");
  expect_refused(write("box.png", whole), "expected a volume bake");

  BakeFile vertex = box.file;
  vertex.header.mode = BakeMode::vertex;
  vertex.header.parts = {{"box", 0, uint32_t(vertex.data.size())}};
  const std::string vertex_path = box.dir.filePath("vertex.lgbake").toStdString();
  write_bake_file(vertex_path, vertex);
  expect_refused(vertex_path, "a vertex bake, expected a volume bake; a vertex bake opens with its mesh");
}

TEST(BakeView, TheCommandExitsNonZeroAndSaysWhichFile) {
  QTemporaryDir dir;
  const QString missing = dir.filePath("missing.vti"), png = dir.filePath("shot.png");
  QProcess inspect;
  inspect.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph-inspect"), {"--bake", missing, "--screenshot", png});
  ASSERT_TRUE(inspect.waitForFinished(60'000));
  EXPECT_EQ(inspect.exitCode(), 2);
  EXPECT_TRUE(QString::fromUtf8(inspect.readAllStandardError()).contains(missing));
  EXPECT_TRUE(QFile::exists(png));  // the window, with the message, is still written
}

// Help and version need no X server: without DISPLAY (and without a platform chosen) the
// inspector still prints them and exits 0; Qt's xcb platform would abort for want of a display.
TEST(BakeView, HelpAndVersionNeedNoDisplay) {
  for (const char* flag : {"--help", "--version"}) {
    QProcess inspect;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    inspect.setProcessEnvironment(env);
    inspect.start(QStringLiteral(LUMAGRAPH_BINARY_DIR "/lumagraph-inspect"), {QString::fromLatin1(flag)});
    ASSERT_TRUE(inspect.waitForFinished(60'000));
    const QString out = QString::fromUtf8(inspect.readAllStandardOutput());
    EXPECT_EQ(inspect.exitCode(), 0) << flag << ": " << inspect.readAllStandardError().toStdString();
    EXPECT_TRUE(out.contains(QStringLiteral("lumagraph-inspect"))) << flag << ": " << out.toStdString();
  }
}

}  // namespace
}  // namespace lg
