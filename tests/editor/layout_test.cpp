// The default layout: columns by depth, no overlaps, history links do not loop it.
#include "editor/layout.h"

#include <gtest/gtest.h>

#include "graph/graph_io.h"

namespace lg::editor {
namespace {

TEST(Layout, ColumnsFollowLinksAndBoxesNeverOverlap) {
  Diagnostics d;
  std::optional<Graph> g = load_graph_file(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/default.json", d);
  ASSERT_TRUE(g);
  const Position size{180, 120};
  const auto placed = layered_layout(*g, [&](const std::string&) { return size; });
  ASSERT_EQ(placed.size(), g->nodes.size());
  for (const GraphLink& l : g->links) {
    if (l.from.node == l.to.node) continue;  // gtao's history
    EXPECT_LT(placed.at(l.from.node)[0], placed.at(l.to.node)[0]) << l.from.text();
  }
  for (const auto& [a, pa] : placed)
    for (const auto& [b, pb] : placed) {
      if (a >= b) continue;
      EXPECT_TRUE(std::abs(pa[0] - pb[0]) >= size[0] || std::abs(pa[1] - pb[1]) >= size[1]) << a << " " << b;
    }
}

}  // namespace
}  // namespace lg::editor
