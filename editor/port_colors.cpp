#include "editor/port_colors.h"

#include <cmath>
#include <map>

namespace lg::editor {

static const std::map<std::string, QColor>& colors() {
  static const std::map<std::string, QColor> table = [] {
    std::map<std::string, QColor> t;
    const std::vector<PortType> types = all_port_types();
    for (size_t i = 0; i < types.size(); ++i) {
      // The golden-angle step keeps neighbours in the list far apart in hue.
      const double hue = std::fmod(0.08 + 0.618034 * double(i), 1.0);
      t[types[i].name()] = QColor::fromHsvF(hue, 0.62, 0.95);
      t.try_emplace(types[i].kind, t[types[i].name()].lighter(130));
    }
    return t;
  }();
  return table;
}

QColor port_color(const PortType& type) {
  const auto& table = colors();
  if (auto it = table.find(type.is_wildcard() ? type.kind : type.name()); it != table.end()) return it->second;
  return QColor(200, 200, 200);
}

}  // namespace lg::editor
