// lumagraph-inspect FILE [--screenshot PNG]: shows an environment probe (an equirectangular
// .hdr or .exr) on a sphere beside its L2 SH reconstruction and the error between them.
// lumagraph-inspect --bake BAKE [--screenshot PNG]: shows a baked occlusion volume (NAME.vti or
// NAME.lgbake of `lumagraph bake --mode volume`) as three slices coloured by visibility.
// lumagraph-inspect --bake NAME.lgbake --mesh MESH [--screenshot PNG]: shows a vertex bake on
// the mesh (or scene) it was baked from, coloured by each vertex's visibility.
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
  args.setApplicationDescription(QStringLiteral("Inspects environment probes and baked occlusion volumes."));
  args.addHelpOption();
  args.addPositionalArgument(QStringLiteral("file"), QStringLiteral("Environment (.hdr, .exr)."),
                             QStringLiteral("[file]"));
  const QCommandLineOption bake(QStringLiteral("bake"),
                                QStringLiteral("A volume bake to show instead (.vti or .lgbake of lumagraph bake)."),
                                QStringLiteral("BAKE"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Write the window to a PNG and exit."), QStringLiteral("PNG"));
  const QCommandLineOption mesh(QStringLiteral("mesh"),
                                QStringLiteral("The mesh or scene a vertex bake (--bake NAME.lgbake) was baked from."),
                                QStringLiteral("MESH"));
  args.addOption(bake);
  args.addOption(mesh);
  args.addOption(screenshot);
  args.process(app);
  if (args.positionalArguments().size() != (args.isSet(bake) ? 0 : 1)) args.showHelp(1);
  const QString file = args.isSet(bake) ? args.value(bake) : args.positionalArguments().front();

  lg::InspectorWidget inspector;
  inspector.setWindowTitle(QStringLiteral("Lumagraph Inspector — %1").arg(file));
  inspector.resize(args.isSet(bake) ? 1100 : 1400, args.isSet(bake) ? 820 : 620);
  inspector.show();
  const bool opened = args.isSet(mesh)   ? inspector.open_vertex_bake(file, args.value(mesh))
                      : args.isSet(bake) ? inspector.open_bake(file)
                                         : inspector.open_environment(file);
  (opened ? std::cout : std::cerr) << inspector.summary().toStdString() << "\n";
  if (!args.isSet(screenshot)) return app.exec();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  if (!inspector.grab().save(args.value(screenshot))) {
    std::cerr << "lumagraph-inspect: could not write " << args.value(screenshot).toStdString() << "\n";
    return 1;
  }
  return opened ? 0 : 2;
}
