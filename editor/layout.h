// A tidy default layout for graphs whose file has no positions: nodes in columns by their
// longest distance from a source (history links, the only legal cycles, are ignored), each
// column ordered by where its inputs sit, so links mostly run left to right without crossing.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "editor/graph_edits.h"

namespace lg::editor {

using NodeSize = std::function<Position(const std::string& id)>;  // width, height

// Top-left corners for every node of `graph`.
std::map<std::string, Position> layered_layout(const Graph& graph, const NodeSize& size);

}  // namespace lg::editor
