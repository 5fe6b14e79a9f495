// lumagraph-inspect FILE [--screenshot PNG]: shows an environment probe (an equirectangular
// .hdr or .exr) on a sphere beside its L2 SH reconstruction and the error between them.
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <iostream>

#include "editor/inspector_widget.h"

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("lumagraph-inspect"));

  QCommandLineParser args;
  args.setApplicationDescription(QStringLiteral("Inspects environment probes."));
  args.addHelpOption();
  args.addPositionalArgument(QStringLiteral("file"), QStringLiteral("Environment (.hdr, .exr)."));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Write the window to a PNG and exit."), QStringLiteral("PNG"));
  args.addOption(screenshot);
  args.process(app);
  if (args.positionalArguments().size() != 1) args.showHelp(1);

  lg::InspectorWidget inspector;
  inspector.setWindowTitle(QStringLiteral("Lumagraph Inspector — %1").arg(args.positionalArguments().front()));
  inspector.resize(1400, 620);
  inspector.show();
  const bool opened = inspector.open_environment(args.positionalArguments().front());
  std::cout << inspector.summary().toStdString() << "\n";
  if (!args.isSet(screenshot)) return app.exec();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  if (!inspector.grab().save(args.value(screenshot))) {
    std::cerr << "lumagraph-inspect: could not write " << args.value(screenshot).toStdString() << "\n";
    return 1;
  }
  return opened ? 0 : 2;
}
