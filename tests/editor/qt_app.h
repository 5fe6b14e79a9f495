// The QApplication of a GUI test, made on first use (after VTK's GL format is the default), so
// that listing the tests needs no display.
#pragma once

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QSurfaceFormat>

namespace lg::test {

inline QApplication& qt_app() {
  static int argc = 1;
  static char name[] = "lumagraph-test";
  static char* argv[] = {name, nullptr};
  static QApplication* app = [] {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    return new QApplication(argc, argv);
  }();
  return *app;
}

// Lets queued work (deferred link checks, repaints) run.
inline void settle() {
  for (int i = 0; i < 3; ++i) QApplication::processEvents();
}

}  // namespace lg::test
