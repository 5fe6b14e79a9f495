// lumagraph-editor [GRAPH] [--screenshot FILE]: edits graph files, with a live preview rendered
// by the runtime off the UI thread (--no-preview leaves it out). With --screenshot it opens the
// graph, lays it out, waits for the first preview, writes the window to a PNG and exits (for
// docs and GUI tests); --select ID shows that node's parameters in it, or with --inspector the
// Inspector dock instead (an env.load node's file, a gi.irradiance_volume node's live probes).
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QEventLoop>
#include <QSurfaceFormat>
#include <QTimer>
#include <iostream>

#include "editor/headless_help.h"
#include "editor/canvas.h"
#include "editor/inspector_widget.h"
#include "editor/main_window.h"
#include "editor/runtime_preview.h"

int main(int argc, char** argv) {
  // VTK's view in the inspector needs its GL format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  lg::editor::headless_when_only_text_is_asked(argc, argv);
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("lumagraph-editor"));
  QApplication::setApplicationVersion(QStringLiteral(LUMAGRAPH_VERSION));
  QApplication::setOrganizationName(QStringLiteral("lumagraph"));

  QCommandLineParser args;
  args.setApplicationDescription(QStringLiteral("Edits Lumagraph render graphs."));
  args.addHelpOption();
  args.addVersionOption();
  args.addPositionalArgument(QStringLiteral("graph"), QStringLiteral("Graph file to open."), QStringLiteral("[GRAPH]"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Write the window to a PNG and exit."), QStringLiteral("FILE"));
  args.addOption(screenshot);
  const QCommandLineOption select(QStringLiteral("select"), QStringLiteral("Select a node (for screenshots)."),
                                  QStringLiteral("ID"));
  args.addOption(select);
  const QCommandLineOption inspector(QStringLiteral("inspector"),
                                     QStringLiteral("Show the Inspector dock rather than the parameters."));
  args.addOption(inspector);
  const QCommandLineOption no_preview(QStringLiteral("no-preview"), QStringLiteral("Do not render a live preview."));
  args.addOption(no_preview);
  const QCommandLineOption scene(
      QStringLiteral("scene"), QStringLiteral("Preview on this scene file, glTF or OBJ (default: the built-in world)."),
      QStringLiteral("FILE"));
  args.addOption(scene);
  const QCommandLineOption asset_root(QStringLiteral("asset-root"),
                                      QStringLiteral("A folder the scene file's paths may point into, besides its own "
                                                     "(repeat for more)."),
                                      QStringLiteral("DIR"));
  args.addOption(asset_root);
  args.process(app);
  const QStringList files = args.positionalArguments();
  const bool shoot = args.isSet(screenshot);

  lg::editor::MainWindow window(!shoot);
  if (!files.isEmpty() && !window.open_file(files.front()) && shoot) {
    std::cerr << "lumagraph-editor: could not open " << files.front().toStdString() << "\n";
    return 1;
  }
  window.show();
  if (!args.isSet(no_preview)) {
    std::vector<std::string> roots;
    for (const QString& root : args.values(asset_root)) roots.push_back(root.toStdString());
    window.set_preview(std::make_unique<lg::editor::RuntimePreview>(args.value(scene).toStdString(), roots));
  }
  if (!shoot) {
    if (files.isEmpty()) window.offer_recovery({});
    return app.exec();
  }

  if (args.isSet(inspector)) qobject_cast<QDockWidget*>(window.inspector()->parentWidget())->raise();
  if (args.isSet(select)) window.canvas()->select_nodes({args.value(select).toStdString()});
  // Let the docks and the canvas take their sizes, and the preview arrive, before grabbing.
  QEventLoop settle;
  if (!args.isSet(no_preview) && window.previews_shown() == 0) {
    QObject::connect(&window, &lg::editor::MainWindow::preview_shown, &settle, &QEventLoop::quit);
    QTimer::singleShot(60000, &settle, &QEventLoop::quit);
  } else {
    QTimer::singleShot(300, &settle, &QEventLoop::quit);
  }
  settle.exec();
  window.canvas()->frame_all();
  QApplication::processEvents();
  if (!window.grab().save(args.value(screenshot))) {
    std::cerr << "lumagraph-editor: could not write " << args.value(screenshot).toStdString() << "\n";
    return 1;
  }
  return 0;
}
