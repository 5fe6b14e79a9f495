// `lumagraph`: render, compile, validate and list render graphs, and bake occlusion, from the command line.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace {

constexpr const char* help = R"(usage: lumagraph COMMAND [ARGS]

commands:
  render [GRAPH]    render a graph on a scene and write the image
  compile [GRAPH]   compile a graph against a scene and print the plan
  validate GRAPH    check a graph file and report every error
  nodes             list the node types, their ports and params
  bake MESH         bake ambient occlusion and bent normals (vertex, texel, volume)
  reference [SCENE] path-trace the ground truth that global illumination is measured against
  soak [GRAPH]      render for a long time with hot reloads and world changes; memory per frame

`lumagraph COMMAND --help` describes each command; `lumagraph --version` prints the version. With no GRAPH, render and compile use
the embedded default graph (examples/default.json) and the embedded default scene.
)";

}  // namespace

namespace lg::cli {

int usage_error(const std::string& command, const std::string& message) {
  std::fprintf(stderr, "lumagraph %s: %s\n(see 'lumagraph %s --help')\n", command.c_str(), message.c_str(),
               command.c_str());
  return exit_usage;
}

}  // namespace lg::cli

int main(int argc, char** argv) {
  using namespace lg::cli;
  if (argc < 2) {
    std::fputs(help, stderr);
    return exit_usage;
  }
  std::string command = argv[1];
  std::vector<std::string> rest(argv + 2, argv + argc);
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(help, stdout);
    return exit_ok;
  }
  if (command == "--version") {
    std::puts("lumagraph " LUMAGRAPH_VERSION);
    return exit_ok;
  }
  if (command == "render") return render_command(rest);
  if (command == "compile") return compile_command(rest);
  if (command == "validate") return validate_command(rest);
  if (command == "nodes") return nodes_command(rest);
  if (command == "bake") return bake_command(rest);
  if (command == "reference") return reference_command(rest);
  if (command == "soak") return soak_command(rest);
  std::fprintf(stderr, "lumagraph: unknown command '%s'\n\n%s", command.c_str(), help);
  return exit_usage;
}
