// The `lumagraph` subcommands. Each takes the arguments after its name and returns the
// process exit code: 0 success, 1 usage error, 2 invalid input (graph, scene, schema), 3 writing
// an output failed.
#pragma once

#include <string>
#include <vector>

namespace lg::cli {

inline constexpr int exit_ok = 0;
inline constexpr int exit_usage = 1;
inline constexpr int exit_invalid = 2;
inline constexpr int exit_write = 3;

int compile_command(const std::vector<std::string>& argv);
int validate_command(const std::vector<std::string>& argv);
int nodes_command(const std::vector<std::string>& argv);
int render_command(const std::vector<std::string>& argv);
int bake_command(const std::vector<std::string>& argv);
int reference_command(const std::vector<std::string>& argv);
int soak_command(const std::vector<std::string>& argv);

// Prints "lumagraph COMMAND: MESSAGE" and a pointer to --help; returns exit_usage.
int usage_error(const std::string& command, const std::string& message);

}  // namespace lg::cli
