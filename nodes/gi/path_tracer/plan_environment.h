// The environment a compiled plan lights its scene with, for the CPU tracers (the `reference` and
// `bake --mode probes` commands, and gi.irradiance_volume's in-graph bake): of the plan's active
// nodes, the first env.load (its file, at its intensity) or env.sky (sky and sun); none when it
// keeps neither.
#pragma once

#include "graph/plan.h"
#include "nodes/gi/path_tracer/path_scene.h"

namespace lg {

// Throws what loading the environment's image throws; `who` starts the warning about non-finite
// texels (e.g. "lumagraph bake").
PathEnvironment plan_environment(const Plan& plan, const char* who);

// Whether the plan's scene.gbuffer culls back faces (`fallback` without an active one).
bool plan_culls_backfaces(const Plan& plan, bool fallback);

}  // namespace lg
