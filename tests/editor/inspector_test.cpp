// The inspector shows a real environment: SH from the file, and a non-blank VTK view.
#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <cmath>
#include <set>

#include "editor/env_probe.h"
#include "editor/inspector_widget.h"
#include "qt_app.h"

namespace lg {
namespace {

const char* grace = LUMAGRAPH_SOURCE_DIR "/../shared/data/env/grace.hdr";

TEST(Inspector, ShowsAnEnvironmentBesideItsSh) {
  if (!QFile::exists(grace)) GTEST_SKIP() << "test data missing: " << grace;
  test::qt_app();
  InspectorWidget inspector;
  inspector.resize(1200, 500);
  inspector.show();
  ASSERT_TRUE(inspector.open_environment(grace));
  test::settle();
  EXPECT_TRUE(inspector.summary().contains("L2 SH RMS error")) << inspector.summary().toStdString();
  const QImage image = inspector.grab().toImage();
  ASSERT_FALSE(image.isNull());
  std::set<QRgb> colours;
  for (int y = 0; y < image.height(); y += 5)
    for (int x = 0; x < image.width(); x += 5) colours.insert(image.pixel(x, y));
  EXPECT_GT(colours.size(), 200u) << "the view looks blank";
}

TEST(Inspector, ProbeOfAFileHasFiniteShAndError) {
  if (!QFile::exists(grace)) GTEST_SKIP() << "test data missing: " << grace;
  const EnvProbe probe = load_env_probe(grace);
  EXPECT_GT(probe.image.width, 0u);
  EXPECT_GT(probe.mean_luminance, 0);
  EXPECT_GT(probe.sh.rgb[0][0], 0);
  EXPECT_TRUE(std::isfinite(probe.rms_error));
  EXPECT_GT(probe.relative_rms_error, 0);  // L2 cannot hold a real environment exactly
}

TEST(Inspector, AMissingFileSaysSo) {
  test::qt_app();
  InspectorWidget inspector;
  EXPECT_FALSE(inspector.open_environment("/nonexistent/sky.hdr"));
  EXPECT_TRUE(inspector.summary().contains("sky.hdr"));
}

}  // namespace
}  // namespace lg
