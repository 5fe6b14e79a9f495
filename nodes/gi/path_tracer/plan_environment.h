// The environment a compiled plan lights its scene with, for the CPU tracers (the `reference` and
// `bake --mode probes` commands, and gi.irradiance_volume's in-graph bake): of the plan's active
// nodes, the first env.load (its file, at its intensity) or env.sky (sky and sun); none when it
// keeps neither, or when the scene has no environment (lighting.ibl then counts the environment
// nodes' light as 0: they may stay in the plan for a probe volume's sake).
#pragma once

#include "graph/plan.h"
#include "nodes/gi/path_tracer/path_scene.h"

namespace lg {

// Throws what loading the environment's image throws; `who` starts the warning about non-finite
// texels (e.g. "lumagraph bake").
PathEnvironment plan_environment(const Plan& plan, bool scene_has_environment, const char* who);

// Whether the plan's scene.gbuffer culls back faces (`fallback` without an active one).
bool plan_culls_backfaces(const Plan& plan, bool fallback);

}  // namespace lg
