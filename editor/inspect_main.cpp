// lumagraph-inspect FILE [--screenshot PNG]: shows an environment probe (an equirectangular
// .hdr or .exr) on a sphere beside its L2 SH reconstruction and the error between them.
// lumagraph-inspect --bake BAKE [--screenshot PNG]: shows a baked occlusion volume (NAME.vti or
// NAME.lgbake of `lumagraph bake --mode volume`) as three slices coloured by visibility.
// lumagraph-inspect --bake NAME.lgbake --mesh MESH [--screenshot PNG]: shows a vertex bake on
// the mesh (or scene) it was baked from, coloured by each vertex's visibility.
// lumagraph-inspect --bake NAME.lgprobes [--volume N] [--probe I] [--screenshot PNG]: shows the
// probes of volume N (from 1) of a probe bake (`lumagraph bake --mode probes`), probe I selected.
// lumagraph-inspect --bake NAME.lgprt --mesh MESH [--vertex I] [--screenshot PNG]: shows a PRT bake
// (`lumagraph bake --mode prt`) on its mesh, and vertex I's transfer function on a sphere.
// lumagraph-inspect --dumped NAME.vti [--channel C] [--screenshot PNG]: shows a 3D texture that
// `lumagraph render --dump` wrote (gi.lpv's or gi.voxel's volume; NAME.mipK.vti for mip K) as
// three slices and a volume rendering of channel C (luminance, red, green, blue: log scale; alpha).
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <iostream>
#include <optional>

#include "editor/dumped_volume_view.h"
#include "editor/headless_help.h"
#include "editor/inspector_widget.h"
#include "editor/probe_view.h"
#include "editor/prt_view.h"

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  lg::editor::headless_when_only_text_is_asked(argc, argv);
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("lumagraph-inspect"));
  QApplication::setApplicationVersion(QStringLiteral(LUMAGRAPH_VERSION));

  QCommandLineParser args;
  args.setApplicationDescription(QStringLiteral("Inspects environment probes and baked occlusion volumes."));
  args.addHelpOption();
  args.addVersionOption();
  args.addPositionalArgument(QStringLiteral("file"), QStringLiteral("Environment (.hdr, .exr)."),
                             QStringLiteral("[file]"));
  const QCommandLineOption bake(
      QStringLiteral("bake"),
      QStringLiteral("A bake to show instead: a volume (.vti or .lgbake), probes (.lgprobes) or PRT (.lgprt)."),
      QStringLiteral("BAKE"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Write the window to a PNG and exit."), QStringLiteral("PNG"));
  const QCommandLineOption mesh(QStringLiteral("mesh"),
                                QStringLiteral("The mesh or scene a vertex or PRT bake (--bake NAME.lgbake, NAME.lgprt) "
                                               "was baked from."),
                                QStringLiteral("MESH"));
  const QCommandLineOption volume(QStringLiteral("volume"), QStringLiteral("The probe bake's volume to show (from 1)."),
                                  QStringLiteral("N"), QStringLiteral("1"));
  const QCommandLineOption probe(QStringLiteral("probe"), QStringLiteral("The probe whose maps to show (from 0)."),
                                 QStringLiteral("I"));
  const QCommandLineOption vertex(QStringLiteral("vertex"),
                                 QStringLiteral("The PRT bake's vertex whose transfer to show (from 0)."),
                                 QStringLiteral("I"));
  const QCommandLineOption dumped(
      QStringLiteral("dumped"),
      QStringLiteral("A 3D texture `lumagraph render --dump` wrote (NAME.vti, NAME.mipK.vti) to show instead."),
      QStringLiteral("VTI"));
  const QCommandLineOption channel(QStringLiteral("channel"),
                                   QStringLiteral("The dumped volume's channel: luminance, red, green, blue (log "
                                                  "scale) or alpha."),
                                   QStringLiteral("C"), QStringLiteral("luminance"));
  args.addOption(bake);
  args.addOption(dumped);
  args.addOption(channel);
  args.addOption(mesh);
  args.addOption(volume);
  args.addOption(probe);
  args.addOption(vertex);
  args.addOption(screenshot);
  args.process(app);
  const bool other = args.isSet(bake) || args.isSet(dumped);
  if (args.positionalArguments().size() != (other ? 0 : 1) || (args.isSet(bake) && args.isSet(dumped)))
    args.showHelp(1);
  const QString file = args.isSet(bake)     ? args.value(bake)
                       : args.isSet(dumped) ? args.value(dumped)
                                            : args.positionalArguments().front();

  lg::InspectorWidget inspector;
  inspector.setWindowTitle(QStringLiteral("Lumagraph Inspector — %1").arg(file));
  inspector.resize(args.isSet(bake) ? 1100 : 1400, other ? 820 : 620);  // --bake and --dumped exclude each other
  inspector.show();
  const bool probes = args.isSet(bake) && file.endsWith(QStringLiteral(".lgprobes"));
  const bool prt = args.isSet(bake) && file.endsWith(QStringLiteral(".lgprt"));
  bool opened = false;
  std::optional<lg::VolumeChannel> shown_channel;
  for (lg::VolumeChannel c : {lg::VolumeChannel::luminance, lg::VolumeChannel::red, lg::VolumeChannel::green,
                              lg::VolumeChannel::blue, lg::VolumeChannel::alpha})
    if (args.value(channel).toStdString() == lg::channel_name(c)) shown_channel = c;
  if (args.isSet(dumped) && !shown_channel)
    inspector.show_error(QStringLiteral("--channel %1: expected luminance, red, green, blue or alpha")
                             .arg(args.value(channel)));
  else if (args.isSet(dumped))
    opened = inspector.open_dumped_volume(file, *shown_channel);
  else if (prt && !args.isSet(mesh))
    inspector.show_error(
        QStringLiteral("%1: a PRT bake opens on the mesh or scene it was baked from: add --mesh MESH").arg(file));
  else if (prt)
    opened = inspector.open_prt_bake(file, args.value(mesh));
  else if (args.isSet(mesh))
    opened = inspector.open_vertex_bake(file, args.value(mesh));
  else if (probes)
    opened = inspector.open_probes(file, args.value(volume).toInt() - 1);
  else
    opened = args.isSet(bake) ? inspector.open_bake(file) : inspector.open_environment(file);
  // --probe and --vertex: an index below the count shown, or an error in the view.
  auto index_of = [&](const QCommandLineOption& option, size_t count, const QString& what) -> std::optional<size_t> {
    bool number = false;
    const qulonglong index = args.value(option).toULongLong(&number);
    if (number && index < count) return size_t(index);
    inspector.show_error(QStringLiteral("--%1 %2: expected a %3 from 0 to %4 (%5 has %6)")
                             .arg(option.names().front(), args.value(option), what)
                             .arg(qlonglong(count) - 1)
                             .arg(file)
                             .arg(count));
    return std::nullopt;
  };
  if (opened && probes && args.isSet(probe)) {
    const std::optional<size_t> index = index_of(probe, inspector.probe_state()->probes, QStringLiteral("probe"));
    if (index) inspector.select_probe(*index);
    opened = index.has_value();
  }
  if (opened && prt && args.isSet(vertex)) {
    const std::optional<size_t> index = index_of(vertex, inspector.prt_state()->vertices, QStringLiteral("vertex"));
    if (index) inspector.select_prt_vertex(*index);
    opened = index.has_value();
  }
  (opened ? std::cout : std::cerr) << inspector.summary().toStdString() << "\n";
  if (!args.isSet(screenshot)) return app.exec();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  if (!inspector.grab().save(args.value(screenshot))) {
    std::cerr << "lumagraph-inspect: could not write " << args.value(screenshot).toStdString() << "\n";
    return 1;
  }
  return opened ? 0 : 2;
}
