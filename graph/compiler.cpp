#include "graph/compiler.h"

#include <chrono>

#include "graph/compiler/assemble.h"
#include "graph/compiler/cull.h"
#include "graph/compiler/lifetimes.h"
#include "graph/compiler/requirements.h"
#include "graph/compiler/resolve.h"
#include "graph/compiler/schedule.h"
#include "graph/compiler/specialize.h"
#include "graph/compiler/synchronize.h"
#include "graph/compiler/validate.h"

namespace lg {
namespace {

class PhaseTimer {
 public:
  explicit PhaseTimer(CompileResult& result) : result_(result) {}
  template <class F>
  auto run(const char* phase, F&& f) {
    auto start = std::chrono::steady_clock::now();
    auto value = f();
    auto end = std::chrono::steady_clock::now();
    result_.timings.push_back({phase, std::chrono::duration<double, std::milli>(end - start).count()});
    return value;
  }

 private:
  CompileResult& result_;
};

}  // namespace

CompileResult compile(const Graph& graph, const Registry& registry, const CompileOptions& options,
                      Diagnostics& diagnostics) {
  CompileResult result;
  PhaseTimer timer(result);
  auto dump = [&](const char* phase, auto&& make) {
    if (options.keep_dumps) result.dumps.emplace_back(phase, make());
  };

  ResolvedGraph resolved = timer.run("resolve", [&] { return resolve(graph, registry, diagnostics); });
  dump("resolve", [&] { return dump_resolved(resolved); });
  auto order_nodes = timer.run("validate", [&] { return validate(resolved, options.roots, diagnostics); });
  if (!order_nodes || diagnostics.has_errors()) return result;
  dump("validate", [&] { return dump_node_order(resolved, *order_nodes); });

  NodeStates states = timer.run("specialize", [&] { return specialize(resolved, options.scene); });
  dump("specialize", [&] { return dump_node_states(resolved, states); });
  states = timer.run("cull", [&] { return cull(resolved, std::move(states)); });
  dump("cull", [&] { return dump_node_states(resolved, states); });
  timer.run("requirements", [&] {
    check_requirements(resolved, states, options.scene, diagnostics);
    return 0;
  });
  if (diagnostics.has_errors()) return result;

  auto lowered = timer.run(
      "lower", [&] { return lower(resolved, *order_nodes, states, options.frame, options.roots, diagnostics,
                                options.keep_optional_outputs); });
  if (!lowered) return result;
  dump("lower", [&] { return dump_lowered(*lowered); });
  auto order = timer.run("schedule", [&] { return schedule(*lowered); });
  dump("schedule", [&] { return dump_schedule(*lowered, order); });
  auto lives = timer.run("lifetimes", [&] { return lifetimes(*lowered, order); });
  dump("lifetimes", [&] { return dump_lifetimes(*lowered, lives); });
  auto memory = timer.run("alias", [&] { return alias(*lowered, lives, options.alias); });
  dump("alias", [&] { return dump_memory(*lowered, memory); });
  auto barriers = timer.run("synchronize", [&] { return synchronize(*lowered, order, memory); });
  dump("synchronize", [&] { return dump_barriers(*lowered, order, barriers); });

  result.plan = timer.run("assemble", [&] {
    return assemble(graph, resolved, std::move(states), std::move(*lowered), *order_nodes, order, lives,
                    std::move(memory), std::move(barriers),
                    {options.scene.name, options.frame, options.roots, options.keep_optional_outputs});
  });
  return result;
}

}  // namespace lg
