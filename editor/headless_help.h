// Lets --help and --version of the Qt programs answer without an X server: Qt's default
// platform wants a display before the command line is even parsed, so a command line that only
// asks for text selects the offscreen platform (unless QT_QPA_PLATFORM already names one).
#pragma once

#include <QByteArray>
#include <QtGlobal>
#include <string_view>

namespace lg::editor {

inline void headless_when_only_text_is_asked(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if ((arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "-v" || arg == "--version") &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
      qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
  }
}

}  // namespace lg::editor
