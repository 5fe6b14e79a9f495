// One colour per port type, spread around the hue circle in the order of all_port_types(), so
// that a type looks the same on every node; a wildcard input ("texture2d:*") takes the colour
// of its kind's first type, paler.
#pragma once

#include <QColor>

#include "graph/port_type.h"

namespace lg::editor {

QColor port_color(const PortType& type);

}  // namespace lg::editor
