// The lighting of examples/post.json as a graph for the post-processing references: the G-buffer,
// the procedural sky with its SH and prefiltered specular, the DFG table, direct and image-based
// light (result "ibl.color"), optionally followed by post.dof (id "dof", result "dof.color").
#pragma once

#include <string_view>

#include "graph/graph.h"

namespace lg::test {

// `dof_params`: post.dof's params as a JSON object's text; empty: no post.dof.
Graph ibl_graph(std::string_view dof_params = {});

}  // namespace lg::test
