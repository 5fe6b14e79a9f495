// Precomputed radiance transfer, baked per vertex of the world mesh (world_mesh.h) with Embree:
// each vertex's diffuse transfer vector T, so that its irradiance under a distant environment of
// radiance SH coefficients L_k (env.sh_project, convolve_cosine off) is E = sum_k T_k L_k, and
// the light it reflects albedo / pi x E (docs/prt.md).
//   unshadowed:     T_k = integral of max(n.w, 0) Y_k(w) dw, exactly (the cosine lobe's zonal
//                   coefficients turned to n: cosine_lobe_band(l) Y_k(n));
//   shadowed:       the same integral over the directions that escape the scene (visibility);
//   interreflected: plus the light the scene reflects onto the vertex after up to `bounces`
//                   diffuse bounces, per colour channel (the surfaces' diffuse colour, base
//                   colour x (1 - metalness), as the path tracer reads it).
// Monte Carlo: `rays` stratified cosine-distributed directions about the vertex normal; a ray
// that escapes adds pi / rays x Y_k(w) times its throughput; one that hits a surface continues
// (interreflected only) in a cosine-distributed direction about the face it hit, its throughput
// times the diffuse colour there. Every random number is a hash of (seed, vertex, ray,
// dimension), so any range of vertices (a chunk) bakes bit-identically to the same vertices of
// a whole run.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "nodes/gi/path_tracer/path_scene.h"
#include "nodes/raytrace/bake_chunks.h"

namespace lg {

enum class TransferKind { unshadowed, shadowed, interreflected };
const char* transfer_kind_name(TransferKind kind);
std::optional<TransferKind> parse_transfer_kind(std::string_view name);

inline constexpr int kPrtMinOrder = 2, kPrtMaxOrder = 4;
inline constexpr uint32_t kPrtMaxRays = 1u << 20;
inline constexpr uint32_t kPrtMaxBounces = 64;

struct PrtSettings {
  TransferKind kind = TransferKind::interreflected;
  int order = 3;         // highest SH band: (order + 1)^2 coefficients a channel
  uint32_t rays = 256;   // per vertex (unshadowed traces none)
  uint32_t bounces = 2;  // interreflected: diffuse bounces after the vertex's own ray; else 0
  uint64_t seed = 1;
};

// Throws std::invalid_argument naming the setting out of range.
void check_prt_settings(const PrtSettings& settings);

// Floats one vertex holds in a bake: 3 channels of each coefficient (coefficient-major: k * 3 + c).
inline int prt_vertex_floats(int order) {
  return 3 * (order + 1) * (order + 1);
}

struct PrtData {
  std::vector<float> transfer;  // prt_vertex_floats(order) per vertex
  std::vector<float> valid;     // 1 baked; 0 a vertex without a normal (its transfer 0)
};

// Bakes the vertices `range` of the scene's world mesh (scene.surfaces().mesh()). `progress`,
// when given, is called from the calling thread with the vertices done.
PrtData bake_transfer(const PathScene& scene, const PrtSettings& settings, PointRange range,
                      const std::function<void(uint64_t done)>& progress = {});

}  // namespace lg
