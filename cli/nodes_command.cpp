#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/args.h"
#include "cli/commands.h"
#include "graph/json_reader.h"
#include "graph/json_writer.h"
#include "nodes/builtin_schemas.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph nodes [--json]

Lists the node types this build knows, with their ports and params. --json prints the
schemas themselves (the same data the validator and the editor use).
)";

std::string param_line(const ParamSpec& p) {
  std::string line = "    " + p.name + " (" + std::string(param_type_name(p.type));
  if (!p.unit.empty()) line += ", " + p.unit;
  line += ") = " + write_json_compact(p.default_value);
  if (p.min || p.max) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " in [%g, %g]", p.min.value_or(-INFINITY), p.max.value_or(INFINITY));
    line += buf;
  }
  if (!p.values.empty()) {
    line += " one of";
    for (const auto& v : p.values) line += " " + v;
  }
  if (!p.choices.empty()) {
    line += " one of";
    for (double c : p.choices) {
      char buf[32];
      std::snprintf(buf, sizeof buf, " %g", c);
      line += buf;
    }
  }
  return line + ": " + p.doc + "\n";
}

}  // namespace

int nodes_command(const std::vector<std::string>& argv) {
  std::string error;
  auto args = parse_args(argv, {{"--json", "--help"}, {}, {}}, &error);
  if (!args) return usage_error("nodes", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  if (!args->positional.empty()) return usage_error("nodes", "takes no arguments");
  const Registry& registry = builtin_registry();

  if (args->has("--json")) {
    JsonValue root = JsonValue::object();
    root.set("format", "lumagraph-nodes/1");
    JsonValue& types = root.set("port_types", JsonValue::array());
    for (const auto& t : all_port_types()) types.push(t.name());
    JsonValue& nodes = root.set("nodes", JsonValue::array());
    for (const EmbeddedFile& file : embedded_node_schemas()) {
      Diagnostics diagnostics{std::string(file.path)};
      if (auto schema = read_json(file.text, diagnostics)) nodes.push(std::move(*schema));
    }
    std::fputs(write_json(root).c_str(), stdout);
    return exit_ok;
  }
  for (const NodeSchema* s : registry.all()) {
    std::printf("%s%s\n  %s\n", s->type.c_str(), s->is_static ? "  [static, cached]" : "", s->doc.c_str());
    for (const auto& p : s->inputs) {
      std::string flags = std::string(p.optional ? " optional" : "") + (p.history ? " history" : "");
      std::printf("  in  %-14s %s%s\n", p.name.c_str(), p.type.name().c_str(),
                  flags.empty() ? "" : (std::string(16 - std::min<size_t>(16, p.type.name().size()), ' ') + flags).c_str());
    }
    for (const auto& p : s->outputs) std::printf("  out %-14s %s\n", p.name.c_str(), p.type.name().c_str());
    if (!s->params.empty()) std::printf("  params:\n");
    for (const auto& p : s->params) std::fputs(param_line(p).c_str(), stdout);
    for (const ParamPreset& preset : s->presets) {
      std::string values;
      for (const auto& [param, value] : preset.values)
        values += (values.empty() ? "" : ", ") + s->params[param].name + " = " + write_json_compact(value);
      std::printf("  preset %s (%s): %s\n", preset.name.c_str(), values.c_str(), preset.doc.c_str());
    }
    std::printf("\n");
  }
  return exit_ok;
}

}  // namespace lg::cli
